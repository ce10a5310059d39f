#include "cli/run_support.h"

#include <unistd.h>

#include <iostream>

#include "cli/exit_codes.h"

namespace taa::cli {

RunContext::RunContext(const spec::CaseSpec& spec, const std::string& device, bool validate,
                       RenderOptions renderOptions)
    : spec_(spec), validate_(validate) {
  DeviceOptions options;
  options.device = device;
  options.validate = validate;
  scene_ = buildCaseScene(spec);
  device_ = std::make_unique<Device>(options);
  renderer_ = std::make_unique<Renderer>(*device_, spec, *scene_, renderOptions);
}

RunContext::~RunContext() = default;

std::function<void(int)> RunContext::progress() const {
  if (!isatty(STDERR_FILENO)) return {};
  const std::string name = spec_.name;
  const int frames = spec_.script.frames;
  return [name, frames](int f) {
    std::cerr << "\r" << name << ": frame " << f + 1 << "/" << frames << (f + 1 == frames ? "\n" : "") << std::flush;
  };
}

int RunContext::finish() const {
  if (validate_ && device_->validationMessages() > 0) {
    std::cerr << spec_.name << ": " << device_->validationMessages() << " validation message(s)\n";
    return kRegression;
  }
  return kPass;
}

}  // namespace taa::cli
