// The SPIR-V cache of users' resolves (user/spirv_cache.h): a second compile comes from the
// cache until a file it read changes, a damaged entry is compiled again, the key keeps its parts
// apart, and an entry keeps what the source declares.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "support/fifo_guard.h"
#include "support/shader_folder.h"
#include "support/text.h"
#include "user/glsl_compiler.h"

namespace taa::user::spirv_cache_test {

namespace fs = std::filesystem;
using SpirvCacheTest = test::ShaderFolderTest;

TEST_F(SpirvCacheTest, SecondCompileComesFromTheCacheUntilAnIncludeChanges) {
  write("lib/k.glsl", "const float K = 0.5;\n");
  const auto file = write("cached.comp", R"(#version 450
#include "taa_user.h"
#include "lib/k.glsl"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p) * K, 1.0));
}
)");
  // A fresh cache folder of its own: the process remembers what it did per cache key.
  options_.cacheDir = dir_ / "cache_provenance";
  const auto first = compileComputeShader(file, options_);
  const auto second = compileComputeShader(file, options_);
  EXPECT_FALSE(first.fromCache);
  EXPECT_TRUE(second.fromCache);
  EXPECT_EQ(first.provenance, "compiled by glslang: no cache entry");
  // The second lookup was served by the cache, but this process compiled the shader: the
  // run log must not claim the cache saved the compile.
  EXPECT_EQ(second.provenance, first.provenance);
  EXPECT_EQ(first.spirv, second.spirv);
  EXPECT_EQ(first.includes, second.includes);
  // Same main file, edited header: a stale cache entry would keep K = 0.5.
  write("lib/k.glsl", "const float K = 0.25;\n");
  const auto third = compileComputeShader(file, options_);
  EXPECT_FALSE(third.fromCache);
  EXPECT_NE(third.spirv, first.spirv);
  EXPECT_NE(third.provenance.find("recompiled by glslang: "), std::string::npos) << third.provenance;
  EXPECT_NE(third.provenance.find("k.glsl changed since it was cached"), std::string::npos)
      << third.provenance;
  // A corrupted entry is recompiled, not used.
  for (const auto& e : fs::directory_iterator(options_.cacheDir))
    if (e.path().extension() == ".spv") std::ofstream(e.path(), std::ios::binary) << "garbage!";
  const auto fourth = compileComputeShader(file, options_);
  EXPECT_FALSE(fourth.fromCache);
  EXPECT_EQ(fourth.spirv, third.spirv);
}

// The cache key's parts are kept apart: a `#define` given as an option and the same line at the
// top of the source are different programs (GLSL wants #version first), so the second must be
// compiled, and refused, not served the first one's SPIR-V.
TEST_F(SpirvCacheTest, ADefineOptionAndTheSameLineInTheSourceAreDifferentEntries) {
  const std::string body = R"(#version 450
#include "taa_user.h"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p) * SCALE, 1.0));
}
)";
  options_.cacheDir = dir_ / "cache_define_boundary";
  options_.defines = {"SCALE=0.5"};
  const auto file = write("boundary.comp", body);
  EXPECT_FALSE(compileComputeShader(file, options_).fromCache);
  options_.defines.clear();
  write("boundary.comp", "#define SCALE 0.5\n" + body);
  EXPECT_NE(compileError(file).find("version"), std::string::npos);
}

// A cache entry keeps what the source declares: a shader with its own constant comes from the
// cache the second time, with the constant's name, type and id (name and type tell a removed
// constant from a mistyped name; the id is the compile's to range-check).
TEST_F(SpirvCacheTest, ACachedShaderKeepsItsDeclaredConstants) {
  options_.cacheDir = dir_ / "cache_constants";
  const auto file = write("constants.comp", R"(#version 450
#include "taa_user.h"
layout(constant_id = 3) const float kScale = 0.5;
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p) * kScale, 1.0));
}
)");
  const auto first = compileComputeShader(file, options_);
  const auto second = compileComputeShader(file, options_);
  ASSERT_EQ(first.constants.size(), 1u);
  EXPECT_FALSE(first.fromCache);
  EXPECT_TRUE(second.fromCache);
  ASSERT_EQ(second.constants.size(), 1u);
  EXPECT_EQ(second.constants[0].name, "kScale");
  EXPECT_EQ(second.constants[0].type, ParamType::Float);
  EXPECT_EQ(second.constants[0].id, 3);
  // A forged constant line (an id out of range, a line without a name or with words after it)
  // is a damaged entry: compiled again, and the constant read from the source.
  for (const std::string forged : {"con float -7 kScale\n", "con float 99999999999999999999 kScale\n",
                                   "con float 3\n", "con float 3 kScale extra\n"}) {
    for (const auto& e : fs::directory_iterator(options_.cacheDir))
      if (e.path().extension() == ".deps") {
        std::string deps = test::readFile(e.path());
        const size_t at = deps.find("con float 3 kScale\n");
        ASSERT_NE(at, std::string::npos) << deps;
        std::ofstream(e.path(), std::ios::binary)
            << deps.replace(at, std::string("con float 3 kScale\n").size(), forged);
      }
    const auto again = compileComputeShader(file, options_);
    EXPECT_FALSE(again.fromCache) << forged;
    ASSERT_EQ(again.constants.size(), 1u);
    EXPECT_EQ(again.constants[0].id, 3);
  }
}

// Under an entry's names only files the cache wrote are read: a FIFO is never waited on (the
// compile would hang), a link never followed; the shader is compiled again and the name taken
// back. A cache folder that cannot be written costs the next run a compile, not this one its
// shader, and the run log's provenance says so.
TEST_F(SpirvCacheTest, OnlyFilesTheCacheWroteAreReadAndAnUnwritableFolderIsANote) {
  options_.cacheDir = dir_ / "cache_hostile";
  const auto file = write("hostile.comp", R"(#version 450
#include "taa_user.h"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p) * 0.75, 1.0));
}
)");
  const auto first = compileComputeShader(file, options_);
  fs::path deps, spv;
  for (const auto& e : fs::directory_iterator(options_.cacheDir))
    (e.path().extension() == ".deps" ? deps : spv) = e.path();
  ASSERT_FALSE(deps.empty());
  ASSERT_FALSE(spv.empty());

  fs::remove(deps);
  ASSERT_EQ(::mkfifo(deps.c_str(), 0600), 0);
  const auto second =
      test::readWithoutWaitingOn(deps, [&] { return compileComputeShader(file, options_); });
  EXPECT_FALSE(second.fromCache);
  EXPECT_EQ(second.spirv, first.spirv);
  EXPECT_NE(second.provenance.find("not a file the cache wrote"), std::string::npos)
      << second.provenance;
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(deps)));

  const fs::path elsewhere = dir_ / "elsewhere.spv";  // the same words, outside the folder
  fs::copy_file(spv, elsewhere, fs::copy_options::overwrite_existing);
  fs::remove(spv);
  fs::create_symlink(elsewhere, spv);
  const auto third = compileComputeShader(file, options_);
  EXPECT_FALSE(third.fromCache) << "a link in the cache was followed";
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(spv)));
  EXPECT_TRUE(compileComputeShader(file, options_).fromCache);

  write("a_file", "x");
  options_.cacheDir = dir_ / "src" / "a_file" / "cache";
  const auto fourth = compileComputeShader(file, options_);
  EXPECT_FALSE(fourth.fromCache);
  EXPECT_EQ(fourth.spirv, first.spirv);
  EXPECT_NE(fourth.provenance.find("compiled by glslang: no cache entry; not cached: cannot write"),
            std::string::npos)
      << fourth.provenance;
}

}  // namespace taa::user::spirv_cache_test
