// GPU time per frame of the raster pass and of the temporal resolve, from the
// renderer's timestamp queries (manual time), on whatever device the context picks
// (lavapipe unless TAA_DEVICE names another). Counters: ms per frame of each pass,
// ns per output pixel of the resolve.
//
//   build/bench/taa_bench --benchmark_filter=GBuffer
//   build/bench/taa_bench --benchmark_filter=Resolve
// lavapipe timings vary by tens of percent between runs on a shared machine; compare
// presets with --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
// and read the medians.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>

#include "api/renderer.h"
#include "bench_context.h"
#include "case/case_loader.h"
#include "scene/build_scene.h"

namespace {

using namespace taa;

// Renders `json` frame after frame; each iteration's time is the GPU time of `pass`
// ("frame" = every pass of the frame). Extra counters: every pass's mean ms.
void runCase(benchmark::State& state, const std::string& json, const std::string& pass) {
  const auto spec = cases::parseCase(json, std::filesystem::path(TAA_SOURCE_DIR) / "cases/bench.json").spec;
  const auto scene = scene::buildScene(spec);
  Renderer renderer(taa::bench::context(), spec, scene);
  int frame = 0;
  for (int warm = 0; warm < 3; ++warm) renderer.renderFrame(frame++, false);  // first-use compilation
  std::map<std::string, double> sums;
  int64_t n = 0;
  for (auto _ : state) {
    const auto r = renderer.renderFrame(frame++, false);
    double ms = 0.0;
    for (const auto& [name, t] : r.gpuMs) {
      sums[name] += t;
      if (name == pass || pass == "frame") ms += t;
    }
    ++n;
    state.SetIterationTime(ms / 1000.0);
  }
  for (const auto& [name, total] : sums) state.counters[name + "_ms"] = total / double(n);
  if (pass == "taa_resolve" && sums.count(pass))
    state.counters["resolve_ns_per_px"] =
        sums[pass] / double(n) * 1e6 / double(spec.render.width) / double(spec.render.height);
}

std::string sized(int w, int h, const std::string& rest) {
  return R"({"render": {"width": )" + std::to_string(w) + R"(, "height": )" + std::to_string(h) +
         R"(}, "script": {"frames": 100000}, "camera": {"strafe": {"speed": 1, "distance": 1}}, )" + rest + "}";
}

void BM_GBuffer(benchmark::State& state) {
  runCase(state, sized(int(state.range(0)), int(state.range(1)), R"("scene": {"builtin": "open_area"}, "taa": {"mode": "off"})"),
          "gbuffer");
}
BENCHMARK(BM_GBuffer)->Args({320, 180})->Args({1280, 720})->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);

// The presets the resolve target compares: a minimal 3x3 YCoCg clip, the default
// settings, and the most expensive combination of the resolve's techniques.
const char* kMinimalClip =
    R"("taa": {"history_filter": "bilinear", "velocity_sampling": "pixel", "rectify": "clip", "color_space": "ycocg"})";
const char* kDefault = R"("taa": {})";
const char* kExpensive =
    R"("taa": {"history_filter": "catmull_rom_16", "velocity_sampling": "closest3x3", "rectify": "clip",
              "variance_clip": true, "shaped_neighborhood": true, "color_space": "ycocg", "shrink_chroma": true,
              "tonemap_weighting": "inverse_luma", "depth_culling": true, "anti_ghosting": true,
              "reduce_blend_near_clamp": true, "velocity_alpha": true},
       "movers": [{"shape": "sphere", "start": [-2, 0.5, 1], "end": [2, 0.5, 1]}])";

void BM_Resolve(benchmark::State& state, const char* taa) {
  runCase(state, sized(1280, 720, std::string(R"("scene": {"builtin": "open_area"}, )") + taa), "taa_resolve");
}
BENCHMARK_CAPTURE(BM_Resolve, minimal_ycocg_clip, kMinimalClip)
    ->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(3.0);
// The default preset less one of its two additions over the minimal clip, so the
// cost of each (Catmull-Rom history, depth-closest velocity) can be read off.
BENCHMARK_CAPTURE(BM_Resolve, default_with_pixel_velocity, R"("taa": {"velocity_sampling": "pixel"})")
    ->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(3.0);
BENCHMARK_CAPTURE(BM_Resolve, default_with_bilinear_history, R"("taa": {"history_filter": "bilinear"})")
    ->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(3.0);
BENCHMARK_CAPTURE(BM_Resolve, default_preset, kDefault)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(3.0);
BENCHMARK_CAPTURE(BM_Resolve, most_expensive, kExpensive)
    ->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(3.0);

}  // namespace

BENCHMARK_MAIN();
