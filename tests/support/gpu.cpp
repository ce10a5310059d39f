#include "support/gpu.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <memory>

#include "case/case_loader.h"
#include "core/image_io.h"
#include "frame/readback.h"
#include "scene/build_scene.h"
#include "vk/transfer.h"

namespace taa::test {

Device& device() {
  // Mesa's shader cache where the harness keeps it (vk::shaderCacheDir: $TAA_SHADER_CACHE_DIR,
  // else the user's cache folder), not one of the build tree's own: a fresh clone's tests then
  // load the code the main job compiled instead of compiling every variant again (CI's unit
  // tests spent about 40 s of their 160 s compiling). The cache is keyed by shader and driver,
  // so what a test loads from it is what it would have compiled.
  static std::unique_ptr<Device> dev = std::make_unique<Device>(DeviceOptions{});
  return *dev;
}

vk::Context& gpu() {
  return device().context();
}

vk::Image uploadFloatImage(const Image& image, VkFormat format, const char* name) {
  vk::ImageDesc d;
  d.name = name;
  d.width = uint32_t(image.width);
  d.height = uint32_t(image.height);
  d.format = format;
  d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
            VK_IMAGE_USAGE_STORAGE_BIT;
  vk::Image out(gpu(), d);
  const int channels = format == VK_FORMAT_R16G16_SFLOAT ? 2 : format == VK_FORMAT_R32_SFLOAT ? 1 : 4;
  const bool half = format == VK_FORMAT_R16G16B16A16_SFLOAT || format == VK_FORMAT_R16G16_SFLOAT;
  std::vector<uint8_t> bytes(image.pixelCount() * channels * (half ? 2 : 4));
  for (size_t p = 0; p < image.pixelCount(); ++p)
    for (int c = 0; c < channels; ++c) {
      const float v = c < image.channels ? image.data[p * image.channels + c] : (c == 3 ? 1.0f : 0.0f);
      const size_t i = p * channels + c;
      if (half) {
        const uint16_t bits = floatToHalfBits(v);
        std::memcpy(&bytes[i * 2], &bits, 2);
      } else {
        std::memcpy(&bytes[i * 4], &v, 4);
      }
    }
  vk::uploadImage(gpu(), out, {bytes.data()});
  VkCommandBuffer cmd = gpu().beginCommands();
  out.use(cmd, vk::Use::SampledCompute);
  gpu().submitAndWait(cmd);
  return out;
}

Image downloadImage(vk::Image& image) {
  const int w = int(image.desc().width), h = int(image.desc().height);
  return decodeTarget(vk::readImage(gpu(), image), image.desc().format, w, w, h);
}

spec::CaseSpec caseFromJson(const std::string& json, const std::string& name) {
  const auto path = std::filesystem::path(TAA_SOURCE_DIR) / "cases" / (name + ".json");
  return cases::parseCase(json, path).spec;
}

const Image& auxImage(const FrameRecord& r, const std::string& name) {
  for (const auto& a : r.aux)
    if (a.name == name) return a.image;
  throw std::runtime_error("frame " + std::to_string(r.frame) + " has no buffer " + name);
}

const Image& capturedImage(const FrameRecord& r, Capture c) {
  if (const Image* image = r.capture(c)) return *image;
  throw std::runtime_error("frame " + std::to_string(r.frame) + " has no " + captureName(c) +
                           " capture");
}

std::vector<FrameRecord> renderCaseWith(const spec::CaseSpec& spec, const RenderOptions& options,
                                        const std::vector<int>& framesWithImages) {
  return renderCase(spec, framesWithImages, options);
}

std::vector<FrameRecord> renderCase(const spec::CaseSpec& spec, const std::vector<int>& framesWithImages,
                                    const RenderOptions& options) {
  const auto scene = scene::buildScene(spec);
  Renderer renderer(gpu(), spec, scene, options);
  const auto& wanted = framesWithImages.empty() ? spec.output.frames : framesWithImages;
  std::vector<FrameRecord> out;
  for (int f = 0; f < spec.script.frames; ++f)
    out.push_back(renderer.renderFrame(f, std::find(wanted.begin(), wanted.end(), f) != wanted.end()));
  return out;
}

}  // namespace taa::test
