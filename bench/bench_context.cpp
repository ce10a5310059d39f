#include "bench_context.h"

#include <filesystem>
#include <memory>

namespace taa::bench {

vk::Context& context() {
  static std::unique_ptr<vk::Context> ctx = [] {
    vk::ContextOptions o;
    o.shaderCacheDir = std::filesystem::temp_directory_path() / "taa-bench-shader-cache";
    std::filesystem::create_directories(o.shaderCacheDir);
    return std::make_unique<vk::Context>(o);
  }();
  return *ctx;
}

}  // namespace taa::bench
