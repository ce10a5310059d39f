// Bad scene input (a glTF file that cannot be read, refers outside its folder or
// uses something unsupported). The message names the file, the problem and the
// fix; an InputError (exit code 2).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "core/errors.h"

namespace taa::scene {

class SceneError : public InputError {
 public:
  explicit SceneError(const std::string& message) : InputError(message) {}
  SceneError(const std::filesystem::path& file, const std::string& problem)
      : InputError(file.string() + ": " + problem) {}
};

}  // namespace taa::scene
