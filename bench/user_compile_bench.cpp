// A user resolve's compile: glslang in a child forked for each compile (docs/user-taa.md), the
// repo's GLSL and HLSL examples of the variance clip. Every iteration misses the SPIR-V cache
// (a fresh cache folder), so it pays the fork, the child's preprocess, parse and SPIR-V, and the
// reply. The process's first compile of each language, which builds glslang's built-in tables
// in the parent for every later child, runs before the timing. Times are wall time per compile.
//
//   build/bench/taa_bench --benchmark_filter=UserCompile
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "user/glsl_compiler.h"

namespace {

namespace fs = std::filesystem;
using namespace taa;

void compileFresh(const fs::path& source, const fs::path& cache) {
  user::CompileOptions o;
  o.root = source.parent_path();
  o.cacheDir = cache;
  o.language = user::languageOf(source);
  fs::remove_all(cache);
  const auto c = user::compileComputeShader(source, o);
  if (c.spirv.empty() || c.fromCache) throw std::runtime_error(source.string() + ": no fresh SPIR-V");
}

void BM_UserCompile(benchmark::State& state, const char* file) {
  const fs::path source = fs::path(TAA_SOURCE_DIR) / "examples" / "user_taa" / "cases" / file;
  const fs::path cache = fs::temp_directory_path() / ("taa-bench-user-compile-" + std::to_string(::getpid()));
  compileFresh(source, cache);
  for (auto _ : state) compileFresh(source, cache);
  fs::remove_all(cache);
}
BENCHMARK_CAPTURE(BM_UserCompile, glsl, "variance_clip.comp")->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_UserCompile, hlsl, "variance_clip.hlsl")->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
