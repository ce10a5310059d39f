// The build's SPIR-V files (vk::readSpirvFile): the shader folder is read through the hardened
// reader, so whatever sits there under a shader's name (a FIFO, a link to a device, a file cut
// short) is an environment error naming the file and the fix, never a hang or a module of
// partial words.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.h"
#include "support/fifo_guard.h"
#include "vk/pipeline.h"

namespace taa::vk {
namespace {

namespace fs = std::filesystem;

// The message readSpirvFile refuses `path` with; a failure (not a hang) when it reads or waits.
std::string refusal(const fs::path& path) {
  const std::string what = test::readWithoutWaitingOn(path, [&]() -> std::string {
    try {
      readSpirvFile(path.string());
    } catch (const EnvironmentError& e) {
      return e.what();
    }
    return "read";
  });
  EXPECT_NE(what, "read") << path;
  return what;
}

TEST(SpirvFile, AnythingButWholeWordsInARegularFileIsRefusedByName) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "spirv-file";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string shipped = shaderDir() + "/taa_resolve.comp.spv";
  EXPECT_EQ(readSpirvFile(shipped), loadSpirv("taa_resolve.comp"));

  ASSERT_EQ(::mkfifo((dir / "fifo.spv").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero.spv");
  std::ofstream(dir / "odd.spv", std::ios::binary) << "12345";
  std::ofstream(dir / "empty.spv", std::ios::binary) << "";
  for (const auto& [name, says] : {std::pair<std::string, std::string>{"fifo.spv", "FIFO"},
                                   {"zero.spv", "device"},
                                   {"odd.spv", "5 bytes, not whole 32-bit SPIR-V words"},
                                   {"empty.spv", "0 bytes"},
                                   {"missing.spv", "not found"}}) {
    const std::string what = refusal(dir / name);
    EXPECT_NE(what.find((dir / name).string()), std::string::npos) << what;
    EXPECT_NE(what.find(says), std::string::npos) << what;
    EXPECT_NE(what.find("TAA_SHADER_DIR"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace taa::vk
