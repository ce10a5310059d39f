// Bad scene input (a glTF file that cannot be read, refers outside its folder or
// uses something unsupported). The message names the file, the problem and the
// fix; the CLI maps a SceneError to exit code 2 (bad input).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace taa::scene {

class SceneError : public std::runtime_error {
 public:
  explicit SceneError(const std::string& message) : std::runtime_error(message) {}
  SceneError(const std::filesystem::path& file, const std::string& problem)
      : std::runtime_error(file.string() + ": " + problem) {}
};

}  // namespace taa::scene
