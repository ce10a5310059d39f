// The harness sees the renderer through its public headers (renderer/api/): no file under
// harness/ may include a Vulkan header or the renderer's Vulkan layer, nor a renderer header
// off the allow-list.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

TEST(Layering, HarnessIncludesNoVulkanHeader) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(TAA_SOURCE_DIR) / "harness";
  const std::regex vulkanInclude(R"(^\s*#\s*include\s*[<"](vulkan/|vk/|volk\.h))");
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const auto ext = entry.path().extension();
    if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      EXPECT_FALSE(std::regex_search(line, vulkanInclude))
          << entry.path().string() << ":" << n << ": " << line
          << "\n  the harness reaches the GPU through renderer/api/device.h; move Vulkan code into "
             "renderer/";
  }
  EXPECT_GT(files, 50);  // the walk found the harness
}

// The front door as an allow-list: a quoted include in harness/ resolves to the harness's own
// files, to core/, or to one of the renderer's headers below; anything else (renderer/frame/,
// passes/, vk/, shaders/common/, another scene/ header) fails here. renderer/api/ is the door;
// spec/ is the case file's schema, shared by both sides; the loaders stand listed one by one
// until api/ has a facade for scene, track and user-shader loading.
TEST(Layering, HarnessIncludesOnlyTheRenderersAllowList) {
  namespace fs = std::filesystem;
  const fs::path source(TAA_SOURCE_DIR);
  const fs::path harness = source / "harness", renderer = source / "renderer";
  const std::vector<std::string> allowedPrefixes = {"api/", "spec/"};
  const std::set<std::string> allowedLoaders = {
      "scene/build_scene.h",    "scene/gltf_loader.h",    "scene/scene.h",
      "script/track_bake.h",    "script/tracks.h",        "user/glsl_compiler.h",
      "user/shader_bounds.h",   "user/user_capabilities.h", "user/user_resolve.h"};
  const std::regex quoted(R"(^\s*#\s*include\s*"([^"]+)\")");
  std::set<std::string> rendererHeaders;
  int includes = 0;
  for (const auto& entry : fs::recursive_directory_iterator(harness)) {
    const auto ext = entry.path().extension();
    if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
    std::ifstream in(entry.path());
    std::string line;
    std::smatch m;
    for (int n = 1; std::getline(in, line); ++n) {
      if (!std::regex_search(line, m, quoted)) continue;
      ++includes;
      const std::string path = m[1];
      // The compiler's order: beside the file, the harness's root, the source root (core/).
      if (fs::exists(entry.path().parent_path() / path) || fs::exists(harness / path) ||
          (path.rfind("core/", 0) == 0 && fs::exists(source / path)))
        continue;
      const bool allowed =
          fs::exists(renderer / path) &&
          (allowedLoaders.count(path) != 0 ||
           std::any_of(allowedPrefixes.begin(), allowedPrefixes.end(),
                       [&](const std::string& p) { return path.rfind(p, 0) == 0; }));
      if (allowed) rendererHeaders.insert(path);
      EXPECT_TRUE(allowed) << entry.path().string() << ":" << n << ": " << line
                           << "\n  the harness includes the renderer's renderer/api/ and spec/ "
                              "headers and the listed loaders only; reach the rest through api/";
    }
  }
  EXPECT_GT(includes, 200);  // the walk read the harness's includes
  // A listed loader nobody includes any more leaves the list: the list is what is in use.
  for (const std::string& loader : allowedLoaders)
    EXPECT_TRUE(rendererHeaders.count(loader) != 0) << loader << " is listed but not included";
}
