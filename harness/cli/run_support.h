// What every rendering subcommand sets up: a hermetic shader cache under the output
// folder, the Vulkan context, the scene and the renderer, plus progress output.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "api/device.h"
#include "api/renderer.h"
#include "api/scene_loading.h"
#include "spec/case_spec.h"

namespace taa::cli {

class RunContext {
 public:
  RunContext(const spec::CaseSpec& spec, const std::string& device, bool validate, RenderOptions options = {});
  ~RunContext();

  Device& device() { return *device_; }
  Renderer& renderer() { return *renderer_; }
  // Prints "case: frame i/n" on a terminal; silent otherwise (CI logs stay line-per-check).
  std::function<void(int)> progress() const;
  // Exit code for the run so far: validation messages under --validate are failures.
  int finish() const;

 private:
  const spec::CaseSpec& spec_;
  bool validate_;
  std::unique_ptr<Device> device_;
  std::shared_ptr<const scene::Scene> scene_;
  std::unique_ptr<Renderer> renderer_;
};

}  // namespace taa::cli
