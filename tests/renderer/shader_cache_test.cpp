#include "vk/shader_cache.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace taa::vk {
namespace {

namespace fs = std::filesystem;

// Sets an environment variable for one test and restores it afterwards.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      ::setenv(name, value->c_str(), 1);
    else
      ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(ShaderCache, NeverUnderTheOutputFolderAndOffWhenUnusable) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "shader_cache_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    const ScopedEnv env("TAA_SHADER_CACHE_DIR", (dir / "cache").string());
    EXPECT_EQ(shaderCacheDir(), dir / "cache");
    EXPECT_TRUE(fs::is_directory(dir / "cache"));
  }
  {
    const ScopedEnv env("TAA_SHADER_CACHE_DIR", "off");
    EXPECT_TRUE(shaderCacheDir().empty());
  }
  {
    std::ofstream(dir / "file") << "x";
    const ScopedEnv env("TAA_SHADER_CACHE_DIR", (dir / "file" / "cache").string());
    EXPECT_TRUE(shaderCacheDir().empty()) << "a folder that cannot be created switches it off";
  }
  {
    const ScopedEnv unset("TAA_SHADER_CACHE_DIR", std::nullopt);
    const ScopedEnv xdg("XDG_CACHE_HOME", (dir / "xdg").string());
    EXPECT_EQ(shaderCacheDir(), dir / "xdg" / "taa-harness" / "mesa");
  }
}

}  // namespace
}  // namespace taa::vk
