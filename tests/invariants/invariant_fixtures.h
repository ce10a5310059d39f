// Synthetic frame sequences for the invariant tests: small images, deterministic noise from
// an integer hash, and a driver that feeds frames through the runner's InvariantRun (so
// checks.from_frame and each invariant's frame rule apply as in a real run).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"
#include "invariants/invariant.h"
#include "invariants/registry.h"
#include "run/invariant_run.h"
#include "spec/case_spec.h"

namespace taa::invariants::fixtures {

constexpr int kW = 16;
constexpr int kH = 12;

// Integer hash (lowbias32) -> [0, 1): the same noise on every machine.
inline float noise(int x, int y, int frame, uint32_t seed = 0) {
  uint32_t h =
      uint32_t(x) * 0x9E3779B1u ^ uint32_t(y) * 0x85EBCA77u ^ uint32_t(frame) * 0xC2B2AE3Du ^ seed;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return float(h >> 8) / float(1u << 24);
}

inline Image rgba(float r, float g, float b, int w = kW, int h = kH) {
  Image img(w, h, 4, 1.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at(x, y, 0) = r, img.at(x, y, 1) = g, img.at(x, y, 2) = b;
  return img;
}

inline void setRgb(Image& img, int x, int y, float r, float g, float b) {
  img.at(x, y, 0) = r, img.at(x, y, 1) = g, img.at(x, y, 2) = b;
}

// A textured background: grey levels from the hash, constant over frames.
inline Image background(uint32_t seed = 7) {
  Image img = rgba(0, 0, 0);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const float v = 0.2f + 0.6f * noise(x, y, 0, seed);
      setRgb(img, x, y, v, 0.9f * v, 0.8f * v);
    }
  return img;
}

// Owns the images of one frame and hands out a FrameView of them.
struct Frame {
  int frame = 0;
  bool reset = false;
  Image output, reference, current, ids, velocity;
  std::string sha256;

  FrameView view() const {
    FrameView v;
    v.frame = frame;
    v.historyReset = reset;
    v.output = output.data.empty() ? nullptr : &output;
    v.set(Capture::Reference, reference.data.empty() ? nullptr : &reference);
    v.set(Capture::Current, current.data.empty() ? nullptr : &current);
    v.set(Capture::Ids, ids.data.empty() ? nullptr : &ids);
    v.set(Capture::Velocity, velocity.data.empty() ? nullptr : &velocity);
    v.sha256 = sha256;
    return v;
  }
};

// Runs the invariant `name` alone over `frames` (and `repeat`, the second render) as the
// runner does for a case that lists only it.
inline Outcome runViews(const std::string& name, spec::CheckedCase spec,
                        const std::vector<FrameView>& frames,
                        const std::vector<FrameView>& repeat = {}) {
  spec.checks.invariants = {name};
  run::InvariantRun checks(spec);
  for (const auto& f : frames) checks.observe(f);
  for (const auto& f : repeat) checks.observeRepeat(f);
  auto outcomes = checks.finish();
  EXPECT_EQ(outcomes.size(), 1u);
  return outcomes.empty() ? Outcome{} : outcomes.front();
}

inline Outcome runAll(const std::string& name, const spec::CheckedCase& spec,
                      const std::vector<Frame>& frames, const std::vector<Frame>& repeat = {}) {
  std::vector<FrameView> views, repeats;
  for (const auto& f : frames) views.push_back(f.view());
  for (const auto& f : repeat) repeats.push_back(f.view());
  return runViews(name, spec, views, repeats);
}

inline double valueOf(const Outcome& o, const std::string& name) {
  for (const auto& [k, v] : o.values)
    if (k == name) return v;
  ADD_FAILURE() << "no value '" << name << "' in outcome " << o.name;
  return 0.0;
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The defaults: TAA full, clip in YCoCg, static camera, Halton jitter, no movers.
inline spec::CheckedCase staticCase() {
  spec::CheckedCase s;
  s.name = "synthetic";
  s.script.frames = 16;
  return s;
}

inline spec::CheckedCase moverCase() {
  spec::CheckedCase s = staticCase();
  s.movers.emplace_back();
  return s;
}

}  // namespace taa::invariants::fixtures
