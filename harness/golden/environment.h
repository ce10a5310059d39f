// The environment a frame was rendered in. Two runs with the same fingerprint are
// expected to produce identical bytes (lavapipe is deterministic across runs and
// thread counts); a different driver, device or CPU feature level changes low bits,
// so goldens from elsewhere are compared with tolerances instead.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "api/device.h"

namespace taa::golden {

struct Environment {
  std::string device;       // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string driverName;   // e.g. "llvmpipe"
  std::string driverInfo;   // e.g. "Mesa 22.3.6 (LLVM 15.0.6)"
  std::string apiVersion;   // e.g. "1.3.230"
  std::string cpuFeatures;  // e.g. "x86-64-v4", or "override:sse4.1" under GALLIUM_OVERRIDE_CPU_CAPS

  // One line that identifies the environment; goldens compare bit-exactly only when equal.
  std::string fingerprint() const;
  nlohmann::json toJson() const;
  static Environment fromJson(const nlohmann::json& j);
};

// The x86-64 micro-architecture level of this CPU (from /proc/cpuinfo), or the
// Gallium override in force, which is what lavapipe's code generation follows.
std::string cpuFeatureLevel();

Environment currentEnvironment(const DeviceIdentity& device);

}  // namespace taa::golden
