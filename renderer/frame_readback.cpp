#include "frame_readback.h"

#include <algorithm>
#include <cstring>

#include "core/image_io.h"
#include "readback.h"
#include "vk/transfer.h"

namespace taa {

namespace {

bool wants(const spec::CaseSpec& spec, spec::AuxBuffer b) {
  return std::find(spec.output.aux.begin(), spec.output.aux.end(), b) != spec.output.aux.end();
}

// The top-left width x height of `image`, decoded by its format.
Image readRegion(vk::Context& ctx, vk::Image& image, int width, int height) {
  return decodeTarget(vk::readImage(ctx, image), image.desc().format, int(image.desc().width),
                      width, height);
}

// The mask's bits as one float channel (exact: they stay below 2^24).
Image readMask(vk::Context& ctx, vk::Image& mask, int width, int height) {
  const auto bytes = vk::readImage(ctx, mask);
  Image out(width, height, 1);
  const size_t stride = mask.desc().width;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      uint32_t bits;
      std::memcpy(&bits, &bytes[(size_t(y) * stride + size_t(x)) * 4], 4);
      out.at(x, y) = float(bits);
    }
  return out;
}

}  // namespace

void readFrameColor(vk::Context& ctx, const FrameSources& src, FrameRecord& record) {
  record.color = readRegion(ctx, *src.output, src.outputSize.x, src.outputSize.y);
  record.colorSha256 = pixelSha256(record.color);
}

void readFrameImages(vk::Context& ctx, const spec::CaseSpec& spec, const RenderOptions& o,
                     const FrameSources& src, FrameRecord& record) {
  const int w = src.renderSize.x, h = src.renderSize.y;
  record.hasImages = true;
  readFrameColor(ctx, src, record);
  if (src.reference) {
    vk::Image& ref = src.reference->output();
    record.reference = readRegion(ctx, ref, int(ref.desc().width), int(ref.desc().height));
    record.hasReference = true;
  }
  GBufferTargets& t = *src.targets;
  auto read = [&](vk::Image& img) { return readRegion(ctx, img, w, h); };
  if (wants(spec, spec::AuxBuffer::Depth)) record.aux.push_back({"depth", read(t.depth)});
  if (wants(spec, spec::AuxBuffer::Velocity) || o.captureVelocity)
    record.aux.push_back({"velocity", read(t.velocity)});
  if (wants(spec, spec::AuxBuffer::Normal)) record.aux.push_back({"normal", read(t.normal)});
  if (wants(spec, spec::AuxBuffer::MaterialId) || o.captureIds)
    record.aux.push_back({"material_id", read(t.ids)});
  if (o.captureCurrent) {
    // TSCMAA keeps every eye's input side by side; elsewhere the resolve input is it.
    vk::Image* input = src.tscmaa && src.tscmaa->input() ? src.tscmaa->input() : src.resolveInput;
    const glm::ivec2 size = src.tscmaa ? src.outputSize : src.renderSize;
    record.aux.push_back({"current", readRegion(ctx, *input, size.x, size.y)});
  }
  if (src.adaptive)
    for (auto& c : src.adaptive->readCaptures(src.renderSize)) record.aux.push_back(std::move(c));
  if (o.captureTscmaa && src.tscmaa) {
    record.aux.push_back(
        {"cmaa", readRegion(ctx, src.tscmaa->cmaa(), src.outputSize.x, src.outputSize.y)});
    record.aux.push_back(
        {"tscmaa_mask", readMask(ctx, src.tscmaa->mask(), src.outputSize.x, src.outputSize.y)});
  }
}

std::vector<std::pair<std::string, double>> tscmaaCounters(
    const std::vector<TscmaaCounts>& counts) {
  double edges = 0.0, taaPixels = 0.0;
  for (const auto& c : counts) {
    edges += c.edges.count;
    taaPixels += c.taa.count;
  }
  return {{"tscmaa_edges", edges}, {"tscmaa_taa_pixels", taaPixels}};
}

}  // namespace taa
