// The harness sees the renderer through renderer/api/device.h, renderer.h and frame_record.h:
// no file under harness/ may include a Vulkan header or the renderer's Vulkan layer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

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
