#include "api/device.h"

#include "api/device_error.h"
#include "api/renderer.h"
#include "vk/context.h"
#include "vk/pipeline.h"
#include "vk/pipeline_cache.h"
#include "vk/shader_cache.h"

namespace taa {

std::string DeviceError::report(const std::string&) const {
  return std::string("vulkan: ") + what();
}

Device::Device(const DeviceOptions& options) {
  vk::ContextOptions co;
  co.device = options.device;
  co.validate = options.validate;
  co.devicesAtOnce = options.devicesAtOnce;
  co.shaderCacheDir =
      options.shaderCacheDir.empty() ? vk::shaderCacheDir() : options.shaderCacheDir;
  ctx_ = std::make_unique<vk::Context>(co);
  const vk::DeviceInfo& d = ctx_->info();
  identity_.name = d.name;
  identity_.driverName = d.driverName;
  identity_.driverInfo = d.driverInfo;
  identity_.apiVersion = std::to_string(VK_API_VERSION_MAJOR(d.apiVersion)) + "." +
                         std::to_string(VK_API_VERSION_MINOR(d.apiVersion)) + "." +
                         std::to_string(VK_API_VERSION_PATCH(d.apiVersion));
  identity_.isCpu = d.isCpu;
}

Device::~Device() = default;

int Device::validationMessages() const {
  return ctx_->validationMessages();
}

PipelineCounts Device::pipelineCounts() const {
  const auto s = ctx_->pipelines().stats();
  return {s.created, s.reused};
}

// Defined here rather than in renderer.cpp: it is the facade's entry, and it only unwraps.
Renderer::Renderer(Device& device, const spec::CaseSpec& spec, const scene::Scene& scene,
                   RenderOptions options)
    : Renderer(device.context(), spec, scene, options) {}

std::string shaderFolder() {
  return vk::shaderDir();
}

std::vector<uint32_t> shaderFolderWords(const std::string& fileName) {
  return vk::readSpirvFile(vk::shaderDir() + "/" + fileName);
}

ShaderUseRecord::ShaderUseRecord() : outer_(vk::setShaderUseSet(&names_)) {}

ShaderUseRecord::~ShaderUseRecord() {
  vk::setShaderUseSet(outer_);
  if (outer_) outer_->insert(names_.begin(), names_.end());
}

}  // namespace taa
