// The harness's image comparison on the CPU: LDR-FLIP (the fast float code and the previous
// double one it replaced), HDR-FLIP, and the linear metrics, at 320x180 and 1280x720. Inputs are
// synthetic frame-like pictures (gradients, hard-edged blocks, thin lines) and a shifted,
// re-noised copy, so every FLIP term does work. Times are CPU wall time per comparison.
//
//   build/bench/taa_bench --benchmark_filter='Flip|Metrics'
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>

#include "compare/flip.h"
#include "compare/flip_double.h"
#include "compare/metrics.h"

namespace {

using namespace taa;

float unitHash(uint32_t x, uint32_t y, uint32_t c) {
  uint32_t h = x * 73856093u ^ y * 19349663u ^ c * 83492791u;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  return float(h >> 8) * (1.0f / 16777216.0f);
}

Image picture(int w, int h, bool test, float peak) {
  Image img(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const int sx = test && y > h / 2 ? x + 1 : x;
        float v = 0.15f + 0.6f * float(sx + 7 * c) / float(w) * float(y + 3) / float(h);
        if (((sx / 13) + (y / 9)) % 3 == 0)
          v = 0.2f + 0.6f * unitHash(uint32_t(sx / 13), uint32_t(y / 9), uint32_t(c));
        if (sx % 17 == 4 || y % 23 == 5) v = c == 1 ? 0.95f : 0.05f;
        if (test) v += 0.04f * (unitHash(uint32_t(x), uint32_t(y), uint32_t(c) + 7u) - 0.5f);
        img.at(x, y, c) = std::clamp(v, 0.0f, 1.0f) * peak;
      }
  return img;
}

void setSize(benchmark::State& state, int w, int h) {
  state.counters["ns_per_pixel"] =
      benchmark::Counter(double(w) * double(h), benchmark::Counter::kIsIterationInvariantRate |
                                                    benchmark::Counter::kInvert);
  state.SetLabel(std::to_string(w) + "x" + std::to_string(h));
}

// Args: width, height, threads (0: one per hardware thread).
void BM_FlipLdr(benchmark::State& state) {
  const int w = int(state.range(0)), h = int(state.range(1));
  const Image a = picture(w, h, false, 1.0f), b = picture(w, h, true, 1.0f);
  compare::FlipOptions o;
  o.threads = int(state.range(2));
  for (auto _ : state) benchmark::DoNotOptimize(compare::flipLdr(a, b, o).mean);
  setSize(state, w, h);
}
BENCHMARK(BM_FlipLdr)
    ->Args({320, 180, 1})
    ->Args({1280, 720, 1})
    ->Args({1280, 720, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_FlipLdrDouble(benchmark::State& state) {
  const int w = int(state.range(0)), h = int(state.range(1));
  const Image a = picture(w, h, false, 1.0f), b = picture(w, h, true, 1.0f);
  for (auto _ : state) benchmark::DoNotOptimize(compare::flipLdrDouble(a, b).mean);
  setSize(state, w, h);
}
BENCHMARK(BM_FlipLdrDouble)->Args({320, 180})->Args({1280, 720})->Unit(benchmark::kMillisecond);

// Linear frames with values up to 8: several exposures, each a full LDR-FLIP.
void BM_FlipHdr(benchmark::State& state) {
  const int w = int(state.range(0)), h = int(state.range(1));
  const Image a = picture(w, h, false, 8.0f), b = picture(w, h, true, 8.0f);
  compare::FlipOptions o;
  o.threads = int(state.range(2));
  int exposures = 0;
  for (auto _ : state) {
    const auto r = compare::flipHdr(a, b, o);
    exposures = r.exposures;
    benchmark::DoNotOptimize(r.mean);
  }
  state.counters["exposures"] = exposures;
  setSize(state, w, h);
}
BENCHMARK(BM_FlipHdr)
    ->Args({320, 180, 1})
    ->Args({1280, 720, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_Metrics(benchmark::State& state) {
  const int w = int(state.range(0)), h = int(state.range(1));
  const Image a = picture(w, h, false, 1.0f), b = picture(w, h, true, 1.0f);
  for (auto _ : state) benchmark::DoNotOptimize(compare::computeMetrics(a, b).rmse);
  setSize(state, w, h);
}
BENCHMARK(BM_Metrics)->Args({320, 180})->Args({1280, 720})->Unit(benchmark::kMillisecond);

}  // namespace
