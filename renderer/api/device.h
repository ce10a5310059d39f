// The GPU as the harness sees it: a device to render on, its identity (goldens record it)
// and its validation count. Owns the Vulkan context behind an opaque handle, so nothing
// outside the renderer includes a Vulkan header; Renderer takes a Device.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace taa {

namespace vk {
class Context;
}

struct DeviceOptions {
  // Case-insensitive substring of the device name; empty: $TAA_DEVICE, else lavapipe.
  std::string device;
  bool validate = false;  // Khronos validation layer; messages are counted and printed
  // Mesa's shader cache folder; empty: the user's cache folder (vk/shader_cache.h), which the
  // tests share with the harness they test.
  std::filesystem::path shaderCacheDir;
  // Devices of this process that render at the same time (run -j N's workers): lavapipe's
  // rasteriser threads are shared out among them (vk/context.h).
  int devicesAtOnce = 1;
};

// Identity of the driver a frame came from.
struct DeviceIdentity {
  std::string name;        // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string driverName;  // e.g. "llvmpipe"
  std::string driverInfo;  // e.g. "Mesa 22.3.6 (LLVM 15.0.6)"
  std::string apiVersion;  // e.g. "1.3.230"
  bool isCpu = false;
};

// Pipelines compiled on a device and requests answered with one compiled before
// (a case sharing a pipeline with an earlier case of the run).
struct PipelineCounts {
  size_t created = 0;
  size_t reused = 0;
};

class Device {
 public:
  // Throws EnvironmentError (device_error.h) when no usable device is found.
  explicit Device(const DeviceOptions& options);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  const DeviceIdentity& identity() const { return identity_; }
  // Validation messages of severity warning or error seen so far (0 unless validating).
  int validationMessages() const;
  PipelineCounts pipelineCounts() const;

  // The renderer's view; opaque outside renderer/.
  vk::Context& context() { return *ctx_; }

 private:
  std::unique_ptr<vk::Context> ctx_;
  DeviceIdentity identity_;
};

// The folder SPIR-V is loaded from (build tree or install prefix).
std::string shaderFolder();
// The words of `fileName` in shaderFolder() (e.g. "taa_resolve.comp.lines.spv"), not counted
// as a shader a case runs. Throws EnvironmentError when it is missing or not SPIR-V.
std::vector<uint32_t> shaderFolderWords(const std::string& fileName);

// The build's shaders (SPIR-V file names in shaderFolder()) that renderers load on this thread
// while the record lives, cached pipelines included: which shaders a case runs, so a change
// to one names the cases it can affect. Records nest; an inner one's names reach the outer.
class ShaderUseRecord {
 public:
  ShaderUseRecord();
  ~ShaderUseRecord();
  ShaderUseRecord(const ShaderUseRecord&) = delete;
  ShaderUseRecord& operator=(const ShaderUseRecord&) = delete;
  // Sorted, each once.
  std::vector<std::string> names() const { return {names_.begin(), names_.end()}; }

 private:
  std::set<std::string> names_;
  std::set<std::string>* outer_;
};

}  // namespace taa
