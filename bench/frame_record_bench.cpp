// What the harness does to every frame it reads back, on the CPU: the SHA-256 fingerprint of
// its half-float pixels (pixelSha256), the display mapping (toDisplaySrgb) and the quality
// signature built on it, and the SHA-256 compressors alone (portable rounds and the x86 SHA
// extensions, where the CPU has them). Inputs are frame-sized pictures of exact halves, as a
// half-float target reads back, and of floats that are not halves (an RGBA32F target), which
// the display mapping cannot answer from its table.
//
//   build/bench/taa_bench --benchmark_filter='Sha256|DisplaySrgb|FrameSignature'
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "core/image_io.h"
#include "core/sha256.h"
#include "golden/signature.h"

namespace {

using namespace taa;

// HDR-ish values in [0, 4): a function of the pixel index alone.
Image frame(int w, int h, bool halves) {
  Image img(w, h, 4);
  uint32_t x = 12345u;
  for (float& v : img.data) {
    x = x * 1664525u + 1013904223u;
    const float f = float(x >> 8) * (4.0f / 16777216.0f);
    v = halves ? halfRound(f) : f;
  }
  return img;
}

void BM_PixelSha256(benchmark::State& state) {
  const Image img = frame(int(state.range(0)), int(state.range(1)), true);
  for (auto _ : state) benchmark::DoNotOptimize(pixelSha256(img));
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(img.data.size() * 2));
}
BENCHMARK(BM_PixelSha256)->Args({320, 180})->Args({1280, 720})->Unit(benchmark::kMillisecond);

void BM_DisplaySrgb(benchmark::State& state) {
  const Image img = frame(int(state.range(0)), int(state.range(1)), state.range(2) != 0);
  for (auto _ : state) benchmark::DoNotOptimize(toDisplaySrgb(img));
}
// Third argument: 1 = exact halves (the table), 0 = other floats (the curve itself).
BENCHMARK(BM_DisplaySrgb)->Args({320, 180, 1})->Args({320, 180, 0})->Unit(benchmark::kMillisecond);

void BM_FrameSignature(benchmark::State& state) {
  const Image img = frame(320, 180, true);
  for (auto _ : state) benchmark::DoNotOptimize(golden::frameSignature(img));
}
BENCHMARK(BM_FrameSignature)->Unit(benchmark::kMillisecond);

// Argument: 0 = portable rounds, 1 = the SHA extensions (skipped where the CPU has none).
void BM_Sha256Compress(benchmark::State& state) {
  const sha256detail::Compress fn =
      state.range(0) ? sha256detail::compressAccelerated() : &sha256detail::compressPortable;
  if (!fn) {
    state.SkipWithError("this CPU has no SHA extensions");
    return;
  }
  const std::vector<uint8_t> bytes(1 << 20, 0x5a);
  uint32_t s[8] = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                   0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  for (auto _ : state) {
    fn(s, bytes.data(), bytes.size() / 64);
    benchmark::DoNotOptimize(s);
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(bytes.size()));
}
BENCHMARK(BM_Sha256Compress)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
