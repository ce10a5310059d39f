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
// files, to core/, or to a renderer header under one of the folders below; anything else
// (renderer/frame/, passes/, vk/, scene/, script/, user/, shaders/common/) fails here.
// renderer/api/ is the door (device, renderer, frame record, options, and the facades for
// scene, track and user-shader loading); spec/ is the case file's schema, shared by both sides.
TEST(Layering, HarnessIncludesOnlyTheRenderersAllowList) {
  namespace fs = std::filesystem;
  const fs::path source(TAA_SOURCE_DIR);
  const fs::path harness = source / "harness", renderer = source / "renderer";
  const std::vector<std::string> allowedPrefixes = {"api/", "spec/"};
  const std::regex quoted(R"(^\s*#\s*include\s*"([^"]+)\")");
  std::set<std::string> usedPrefixes;
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
      const auto prefix =
          std::find_if(allowedPrefixes.begin(), allowedPrefixes.end(),
                       [&](const std::string& p) { return path.rfind(p, 0) == 0; });
      const bool allowed = fs::exists(renderer / path) && prefix != allowedPrefixes.end();
      if (allowed) usedPrefixes.insert(*prefix);
      EXPECT_TRUE(allowed) << entry.path().string() << ":" << n << ": " << line
                           << "\n  the harness includes the renderer's renderer/api/ and spec/ "
                              "headers only; reach the rest through a facade in api/";
    }
  }
  EXPECT_GT(includes, 200);  // the walk read the harness's includes
  // An entry nobody includes any more leaves the list: the list is what is in use.
  for (const std::string& prefix : allowedPrefixes)
    EXPECT_TRUE(usedPrefixes.count(prefix) != 0) << prefix << " is listed but not included";
}

// The door holds behind the harness too: what renderer/api/ and spec/ include is each other,
// core/ and shaders/common/'s declarations shared with GLSL, never the renderer's internals
// (where Vulkan lives) or a Vulkan header. A facade that needs an internal type forward-declares
// it and keeps it behind a handle.
TEST(Layering, RenderersPublicHeadersIncludeNoInternals) {
  namespace fs = std::filesystem;
  const fs::path renderer = fs::path(TAA_SOURCE_DIR) / "renderer";
  const std::vector<std::string> allowed = {"api/", "spec/", "core/", "common/"};
  const std::regex quoted(R"(^\s*#\s*include\s*"([^"]+)\")");
  const std::regex vulkanInclude(R"(^\s*#\s*include\s*<(vulkan/|volk\.h))");
  int headers = 0;
  for (const char* door : {"api", "spec"})
    for (const auto& entry : fs::directory_iterator(renderer / door)) {
      if (entry.path().extension() != ".h") continue;
      ++headers;
      std::ifstream in(entry.path());
      std::string line;
      std::smatch m;
      for (int n = 1; std::getline(in, line); ++n) {
        EXPECT_FALSE(std::regex_search(line, vulkanInclude))
            << entry.path().string() << ":" << n << ": " << line;
        if (!std::regex_search(line, m, quoted)) continue;
        const std::string path = m[1];
        EXPECT_TRUE(std::any_of(allowed.begin(), allowed.end(),
                                [&](const std::string& p) { return path.rfind(p, 0) == 0; }))
            << entry.path().string() << ":" << n << ": " << line
            << "\n  a public header may include api/, spec/, core/ and common/ only; "
               "forward-declare the internal type";
      }
    }
  EXPECT_GT(headers, 10);  // the walk found the doors
}
