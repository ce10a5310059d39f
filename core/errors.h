// The two kinds of error the harness reports. Every error type derives from one of them, and
// the kind alone decides the exit code (README.md), so the command dispatcher catches these
// two and nothing else:
//   InputError        something the user gave is wrong (a case, scene, track, shader, golden,
//                     image file or argument): exit 2; the message names the file, the key and
//                     the fix
//   EnvironmentError  this machine cannot do it (no device, missing shaders, a full disk, a GPU
//                     call that failed): exit 3; nothing in the input is to blame
// As with vk-bootstrap's typed errors, each module throws its own type (SceneError, TrackError,
// GoldenError, ...) so that its callers can catch it by name, and code that only needs the kind
// catches the base.
#pragma once

#include <stdexcept>
#include <string>

namespace taa {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  // What the harness prints for it, every line "error: ..." unless the type knows better (a
  // CaseError prints one line per problem, a UsageError names the command).
  virtual std::string report(const std::string& command) const;
};

class EnvironmentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  // "environment: ..." unless the type knows better (a failed GPU call says "vulkan: ").
  virtual std::string report(const std::string& command) const;
};

}  // namespace taa
