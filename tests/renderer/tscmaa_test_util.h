// Helpers for the TSCMAA tests: cases, running TscmaaPass on synthetic images, and
// reading its mask and list headers.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "passes/tscmaa.h"
#include "scene/build_scene.h"
#include "script/frame_state.h"
#include "support/gpu.h"
#include "vk/timestamps.h"
#include "vk/transfer.h"

namespace taa::tscmaatest {

// A TSCMAA case: `tscmaa` is the body of the "tscmaa" object, `rest` more top-level keys.
inline spec::CaseSpec tscmaaCase(const std::string& tscmaa, const std::string& rest = "",
                                 int w = 160, int h = 90) {
  std::string json = R"({"render": {"width": )" + std::to_string(w) + R"(, "height": )" +
                     std::to_string(h) + R"(}, "taa": {"mode": "tscmaa"}, "tscmaa": {)" + tscmaa +
                     "}";
  if (!rest.empty()) json += ", " + rest;
  return test::caseFromJson(json + "}", "tscmaa_test");
}

// What one TscmaaPass frame on a synthetic image produced.
struct SyntheticRun {
  std::vector<uint32_t> mask;  // row-major, eye 0
  Image cmaa;
  TscmaaCounts counts;
};

inline std::vector<uint32_t> readMask(vk::Image& mask) {
  const auto bytes = vk::readImage(test::gpu(), mask);
  std::vector<uint32_t> out(bytes.size() / 4);
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

// Runs the first frame (no history: edges and CMAA only) on `color` (RGBA16F upload).
inline SyntheticRun runSynthetic(const spec::CaseSpec& spec, const Image& color) {
  TscmaaPass pass(test::gpu(), spec);
  auto in = test::uploadFloatImage(color, VK_FORMAT_R16G16B16A16_SFLOAT);
  auto depth =
      test::uploadFloatImage(Image(color.width, color.height, 1, 0.5f), VK_FORMAT_R32_SFLOAT);
  const auto state = script::frameState(spec, 0);
  ResolveInputs inputs;
  inputs[ResolveInput::Color] = &in;
  inputs[ResolveInput::Depth] = &depth;
  vk::GpuTimer timer(test::gpu());
  VkCommandBuffer cmd = test::gpu().beginCommands();
  pass.record(cmd, timer, state, 0, inputs);
  test::gpu().submitAndWait(cmd);
  SyntheticRun r;
  r.mask = readMask(pass.mask());
  r.cmaa = test::downloadImage(pass.cmaa());
  r.counts = pass.counts()[0];
  return r;
}

// Blocks of random grey levels with noise: edges of every strength and direction.
inline Image blockNoise(int w, int h, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> level(0.0f, 1.5f), noise(-0.04f, 0.04f);
  std::vector<float> blocks(size_t((w / 5 + 1) * (h / 5 + 1)));
  for (float& b : blocks) b = level(rng);
  Image img(w, h, 4, 1.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float base = blocks[size_t((y / 5) * (w / 5 + 1) + x / 5)];
      for (int c = 0; c < 3; ++c)
        img.at(x, y, c) = std::max(0.0f, base * (0.8f + 0.2f * float(c)) + noise(rng));
    }
  return img;
}

inline uint32_t groupsFor(uint32_t count) {
  return (count + TSCMAA_LIST_GROUP - 1) / TSCMAA_LIST_GROUP;
}

// Renders every frame of `spec` with images for every frame.
inline std::vector<FrameRecord> renderAll(const spec::CaseSpec& spec, RenderOptions options = {}) {
  const auto scene = scene::buildScene(spec);
  Renderer renderer(test::gpu(), spec, scene, options);
  std::vector<FrameRecord> out;
  for (int f = 0; f < spec.script.frames; ++f) out.push_back(renderer.renderFrame(f, true));
  return out;
}

inline const Image& aux(const FrameRecord& r, const std::string& name) {
  for (const auto& a : r.aux)
    if (a.name == name) return a.image;
  throw std::runtime_error("no aux image " + name);
}

inline double counter(const FrameRecord& r, const std::string& name) {
  for (const auto& [n, v] : r.stats)
    if (n == name) return v;
  throw std::runtime_error("no counter " + name);
}

}  // namespace taa::tscmaatest
