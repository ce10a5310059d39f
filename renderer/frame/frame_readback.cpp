#include "frame/frame_readback.h"

#include <algorithm>
#include <cstring>

#include "core/image_io.h"
#include "frame/readback.h"
#include "vk/barrier.h"

namespace taa {

namespace {

bool wantsAuxBuffer(const spec::CaseSpec& spec, spec::AuxBuffer b) {
  return std::find(spec.output.aux.begin(), spec.output.aux.end(), b) != spec.output.aux.end();
}

// A mask's bits as one float channel (exact: they stay below 2^24).
Image decodeBits(const uint8_t* bytes, int stride, glm::ivec2 size) {
  Image out(size.x, size.y, 1);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      uint32_t bits;
      std::memcpy(&bits, &bytes[(size_t(y) * size_t(stride) + size_t(x)) * 4], 4);
      out.at(x, y) = float(bits);
    }
  return out;
}

}  // namespace

void FrameReadback::add(Kind kind, std::string name, vk::Image& image, glm::ivec2 size) {
  wanted_.push_back(
      {&image,
       Pending{kind, std::move(name), {}, image.desc().format, int(image.desc().width), size}});
}

void FrameReadback::record(VkCommandBuffer cmd, const spec::CaseSpec& spec, const RenderOptions& o,
                           const FrameSources& src, bool images) {
  wanted_.clear();
  images_ = images;
  add(Kind::Output, "color", *src.output, src.outputSize);
  if (images) {
    if (src.reference) {
      vk::Image& ref = src.reference->output();
      add(Kind::Reference, "reference", ref, {int(ref.desc().width), int(ref.desc().height)});
    }
    // The case's output.aux and the captures share names where both can name a target
    // (velocity, material_id): read once, under that name.
    GBufferTargets& t = *src.targets;
    const glm::ivec2 render = src.renderSize;
    if (wantsAuxBuffer(spec, spec::AuxBuffer::Depth)) add(Kind::Aux, "depth", t.depth, render);
    if (wantsAuxBuffer(spec, spec::AuxBuffer::Velocity) || o.captures.has(Capture::Velocity))
      add(Kind::Aux, captureName(Capture::Velocity), t.velocity, render);
    if (wantsAuxBuffer(spec, spec::AuxBuffer::Normal)) add(Kind::Aux, "normal", t.normal, render);
    if (wantsAuxBuffer(spec, spec::AuxBuffer::MaterialId) || o.captures.has(Capture::Ids))
      add(Kind::Aux, captureName(Capture::Ids), t.ids, render);
    // A stage that keeps every eye's input side by side reads it back; elsewhere the
    // resolve's input is it.
    const std::vector<StageCapture>& stage = src.captures;
    const bool stageCurrent = std::any_of(stage.begin(), stage.end(), [](const StageCapture& c) {
      return c.capture == Capture::Current;
    });
    if (o.captures.has(Capture::Current) && !stageCurrent)
      add(Kind::Aux, captureName(Capture::Current), *src.resolveInput, render);
    for (const StageCapture& c : stage)
      if (o.captures.has(c.capture))
        add(captureInfo(c.capture).bits ? Kind::Bits : Kind::Aux, captureName(c.capture), *c.image,
            c.size);
  }
  // One transition point for every image read, then the copies, then the host's turn.
  vk::BarrierBatch barriers;
  for (auto& [image, p] : wanted_) barriers.use(*image, vk::Use::TransferSrc);
  barriers.flush(cmd);
  ring_.reset();
  pending_.clear();
  for (auto& [image, p] : wanted_) {
    p.slot = ring_.copyImage(cmd, *image);
    pending_.push_back(p);
  }
  ring_.finishCopies(cmd);
  wanted_.clear();
}

void FrameReadback::finish(FrameRecord& record) {
  record.hasImages = images_;
  for (const Pending& p : pending_) {
    const uint8_t* bytes = ring_.data(p.slot);
    if (p.kind == Kind::Bits) {
      record.aux.push_back({p.name, decodeBits(bytes, p.stride, p.size)});
      continue;
    }
    Image image = decodeTarget(bytes, p.format, p.stride, p.size.x, p.size.y);
    if (p.kind == Kind::Output) {
      record.color = std::move(image);
      record.colorSha256 = pixelSha256(record.color);
    } else if (p.kind == Kind::Reference) {
      record.reference = std::move(image);
      record.hasReference = true;
    } else {
      record.aux.push_back({p.name, std::move(image)});
    }
  }
  pending_.clear();
}

}  // namespace taa
