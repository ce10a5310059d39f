// TSCMAA's cost against its edge count and against resolution: the measured
// counterparts of the seed's tables 1 (edge count at a fixed resolution, varied by the
// edge threshold) and 3 (resolution with the edge count it brings). Table 2 (resolution
// at a fixed edge count) falls out of the same rows: the edge pass costs per pixel, the
// indirect passes per edge (cmaa_ns_per_edge). Counters: each pass's mean ms, the mean
// edge and TAA pixel counts.
//
//   build/bench/taa_bench --benchmark_filter=Tscmaa
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "api/renderer.h"
#include "bench_context.h"
#include "case/case_loader.h"
#include "scene/build_scene.h"

namespace {

using namespace taa;

bool isTscmaaPass(const std::string& name) {
  return name.rfind("tscmaa_", 0) == 0;
}

void runTscmaa(benchmark::State& state, int w, int h, const std::string& tscmaa) {
  const std::string json = R"({"render": {"width": )" + std::to_string(w) + R"(, "height": )" +
                           std::to_string(h) +
                           R"(}, "scene": {"builtin": "fence"}, "script": {"frames": 100000},
          "camera": {"strafe": {"speed": 0.6, "distance": 0.4}},
          "taa": {"mode": "tscmaa"}, "tscmaa": {)" +
                           tscmaa + "}}";
  const auto spec =
      cases::parseCase(json, std::filesystem::path(TAA_SOURCE_DIR) / "cases/bench.json").spec;
  const auto scene = scene::buildScene(spec);
  Renderer renderer(taa::bench::context(), spec, scene);
  int frame = 0;
  for (int warm = 0; warm < 3; ++warm)
    renderer.renderFrame(frame++, false);  // first-use compilation
  std::map<std::string, double> sums;
  int64_t n = 0;
  for (auto _ : state) {
    const auto r = renderer.renderFrame(frame++, false);
    double ms = 0.0;
    for (const auto& [name, t] : r.gpuMs) {
      sums[name + "_ms"] += t;
      if (isTscmaaPass(name)) ms += t;
    }
    for (const auto& [name, v] : r.stats) sums[name] += v;
    ++n;
    state.SetIterationTime(ms / 1000.0);
  }
  for (const auto& [name, total] : sums) state.counters[name] = total / double(n);
  const double edges = sums["tscmaa_edges"] / double(n);
  if (edges > 0.0)
    state.counters["cmaa_ns_per_edge"] = sums["tscmaa_cmaa_ms"] / double(n) * 1e6 / edges;
  state.counters["pixels"] = double(w) * double(h);
}

// Table 1: one resolution, the edge count set by the threshold.
void BM_TscmaaEdgeCount(benchmark::State& state) {
  const double threshold = double(state.range(0)) / 1000.0;
  runTscmaa(state, 1280, 720, R"("edge_threshold": )" + std::to_string(threshold));
}
BENCHMARK(BM_TscmaaEdgeCount)
    ->Arg(30)
    ->Arg(45)
    ->Arg(80)
    ->Arg(150)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

// Table 3: the same view at 320x180 .. 1280x720; the edge count grows with resolution.
void BM_TscmaaResolution(benchmark::State& state) {
  runTscmaa(state, int(state.range(0)), int(state.range(0)) * 9 / 16, "");
}
BENCHMARK(BM_TscmaaResolution)
    ->Arg(320)
    ->Arg(640)
    ->Arg(1280)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

}  // namespace
