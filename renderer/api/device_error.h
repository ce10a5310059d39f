// The renderer's errors as the harness sees them, without Vulkan headers: the CLI maps
// EnvironmentError to exit code 3 (nothing to fix in the case) and DeviceError (a GPU call
// failed) likewise. vk/check.h derives its Vulkan-specific error from DeviceError.
#pragma once

#include <stdexcept>

namespace taa {

// The environment cannot run the renderer (no device, missing shaders, missing feature);
// the message says what to install.
class EnvironmentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The case asks for something this device cannot do (say, a sample count it lacks): the
// case has to change, so the CLI maps it to exit code 2 like other bad input. The message
// names the key, what the device offers and the fix.
class UnsupportedSettingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A call into the GPU API failed; the message carries the call, its result, file and line.
class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace taa
