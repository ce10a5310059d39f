// A process that renders on lavapipe loads lavapipe's driver alone (vk/driver_manifests.h):
// which manifests are lavapipe's, where the loader looks, what the user's own choice leaves
// alone, and that the test process's own device came that way.
#include "vk/driver_manifests.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "support/gpu.h"

namespace taa::vk::driver_manifests_test {
namespace {

namespace fs = std::filesystem;

const char* kLavapipe = R"({"file_format_version": "1.0.0",
  "ICD": {"library_path": "libvulkan_lvp.so", "api_version": "1.3.230"}})";
const char* kRadeon = R"({"file_format_version": "1.0.0",
  "ICD": {"library_path": "/usr/lib/x86_64-linux-gnu/libvulkan_radeon.so", "api_version": "1.3.230"}})";

EnvLookup envOf(std::map<std::string, std::string> vars) {
  return [vars = std::move(vars)](const char* name) -> const char* {
    const auto it = vars.find(name);
    return it == vars.end() ? nullptr : it->second.c_str();
  };
}

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

TEST(DriverManifests, TheFoldersAreTheLoadersInItsOrder) {
  auto folders = driverManifestFolders(envOf({{"HOME", "/home/u"}}));
  std::vector<std::string> got;
  for (const auto& f : folders) got.push_back(f.string());
  EXPECT_EQ(got,
            (std::vector<std::string>{"/home/u/.config/vulkan/icd.d", "/etc/xdg/vulkan/icd.d",
                                      "/etc/vulkan/icd.d", "/home/u/.local/share/vulkan/icd.d",
                                      "/usr/local/share/vulkan/icd.d", "/usr/share/vulkan/icd.d"}));
  folders = driverManifestFolders(envOf({{"XDG_CONFIG_HOME", "/c"},
                                         {"XDG_CONFIG_DIRS", "/x::/y"},
                                         {"XDG_DATA_HOME", "/d"},
                                         {"XDG_DATA_DIRS", "/s"}}));
  got.clear();
  for (const auto& f : folders) got.push_back(f.string());
  EXPECT_EQ(got,
            (std::vector<std::string>{"/c/vulkan/icd.d", "/x/vulkan/icd.d", "/y/vulkan/icd.d",
                                      "/etc/vulkan/icd.d", "/d/vulkan/icd.d", "/s/vulkan/icd.d"}));
}

TEST(DriverManifests, OnlyAManifestOfLavapipesLibraryIsLavapipes) {
  EXPECT_TRUE(isLavapipeManifest(kLavapipe));
  EXPECT_TRUE(isLavapipeManifest(R"({"ICD": {"library_path": "/opt/mesa/lib/libvulkan_lvp.so"}})"));
  EXPECT_FALSE(isLavapipeManifest(kRadeon));
  EXPECT_FALSE(isLavapipeManifest(
      R"({"ICD": {"library_path": "/opt/libvulkan_lvp.so/libvulkan_intel.so"}})"));
  for (const char* forged :
       {"", "[]", "{", R"({"ICD": 3})", R"({"ICD": {"library_path": 7}})",
        R"({"ICD": {"library_path": ["libvulkan_lvp.so"]}})",
        R"({"layer": {"library_path": "libvulkan_lvp.so"}})",
        R"({"ICD": {"library_path": "libvulkan_lvp.so"}, "ICD": {"library_path": "x.so"}})"})
    EXPECT_FALSE(isLavapipeManifest(forged)) << forged;
  EXPECT_FALSE(isLavapipeManifest(std::string(100000, '[') + std::string(100000, ']')));
}

TEST(DriverManifests, LavapipesManifestsAloneAreNamedAndHostileEntriesSkipped) {
  const fs::path root = fs::path(TAA_TEST_OUT) / "driver-manifests";
  fs::remove_all(root);
  const fs::path config = root / "config" / "vulkan" / "icd.d",
                 data = root / "data" / "vulkan" / "icd.d";
  write(config / "radeon_icd.x86_64.json", kRadeon);
  write(config / "lvp_icd.x86_64.json", kLavapipe);
  write(config / "broken.json", "{\"ICD\": ");
  write(config / "lvp_icd.txt", kLavapipe);  // not a manifest's name
  write(config / "big.json", std::string(kLavapipe) + std::string(kMaxManifestBytes, ' '));
  ASSERT_EQ(mkfifo((config / "fifo.json").c_str(), 0600), 0);  // read, it would never end
  fs::create_directories(config / "folder.json");
  write(root / "outside" / "mine.json", kLavapipe);  // a link to a manifest is the loader's way too
  fs::create_symlink(root / "outside" / "mine.json", config / "linked.json");
  fs::create_symlink(root / "nowhere.json", config / "dangling.json");
  fs::create_symlink("/dev/zero", config / "device.json");  // endless bytes, were it read
  write(data / "lvp_icd.i686.json",
        R"({"ICD": {"library_path": "/usr/lib/i386-linux-gnu/libvulkan_lvp.so"}})");
  const auto env = envOf({{"XDG_CONFIG_HOME", (root / "config").string()},
                          {"XDG_CONFIG_DIRS", "/nonexistent"},
                          {"XDG_DATA_HOME", "/nonexistent"},
                          {"XDG_DATA_DIRS", (root / "data").string()}});
  EXPECT_EQ(lavapipeOnlyDriverFiles(env), (config / "linked.json").string() + ":" +
                                              (config / "lvp_icd.x86_64.json").string() + ":" +
                                              (data / "lvp_icd.i686.json").string());
  // Drivers the user chose stay the user's.
  for (const char* chosen : {"VK_DRIVER_FILES", "VK_ICD_FILENAMES", "VK_ADD_DRIVER_FILES"}) {
    auto vars = std::map<std::string, std::string>{{"XDG_CONFIG_HOME", (root / "config").string()},
                                                   {chosen, "/some/driver.json"}};
    EXPECT_EQ(lavapipeOnlyDriverFiles(envOf(vars)), "") << chosen;
  }
  EXPECT_EQ(lavapipeOnlyDriverFiles(envOf({{"XDG_CONFIG_HOME", "/nonexistent"},
                                           {"XDG_CONFIG_DIRS", "/nonexistent"},
                                           {"XDG_DATA_HOME", "/nonexistent"},
                                           {"XDG_DATA_DIRS", "/nonexistent"}})),
            "");
}

// The libraries this process has mapped whose file name starts libvulkan_ (the loader is
// libvulkan.so.1; drivers are libvulkan_NAME.so).
std::vector<std::string> mappedDrivers() {
  std::ifstream maps("/proc/self/maps");
  std::vector<std::string> out;
  for (std::string line; std::getline(maps, line);) {
    const size_t slash = line.rfind('/');
    if (slash == std::string::npos) continue;
    const std::string name = line.substr(slash + 1);
    if (name.rfind("libvulkan_", 0) == 0 && std::find(out.begin(), out.end(), name) == out.end())
      out.push_back(name);
  }
  return out;
}

TEST(DriverManifests, TheTestDeviceLoadedLavapipeAlone) {
  const std::string only = lavapipeOnlyDriverFiles(std::getenv);
  if (only.empty())
    GTEST_SKIP() << "drivers chosen in the environment, or no lavapipe manifest found";
  (void)test::gpu();
  EXPECT_EQ(mappedDrivers(), std::vector<std::string>{"libvulkan_lvp.so"});
  EXPECT_EQ(std::getenv("VK_DRIVER_FILES"), nullptr) << "the choice must not reach child processes";
}

}  // namespace
}  // namespace taa::vk::driver_manifests_test
