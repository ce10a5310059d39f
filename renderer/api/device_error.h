// The renderer's errors as the harness sees them, without Vulkan headers, each of one of
// core/errors.h's two kinds: a setting the device lacks is bad input (exit 2), a failed GPU
// call the environment (exit 3). vk/check.h derives its Vulkan-specific error from DeviceError;
// EnvironmentError (no device, missing shaders, a missing feature) is core/errors.h's own.
#pragma once

#include <string>

#include "core/errors.h"

namespace taa {

// The case asks for something this device or renderer cannot do (say, a sample count the
// device lacks): the case has to change. The message names the key, what is offered and the fix.
class UnsupportedSettingError : public InputError {
 public:
  using InputError::InputError;
};

// A call into the GPU API failed; the message carries the call, its result, file and line.
class DeviceError : public EnvironmentError {
 public:
  using EnvironmentError::EnvironmentError;
  std::string report(const std::string& command) const override;
};

}  // namespace taa
