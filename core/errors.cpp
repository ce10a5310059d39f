#include "core/errors.h"

namespace taa {

std::string InputError::report(const std::string&) const {
  return std::string("error: ") + what();
}

std::string EnvironmentError::report(const std::string&) const {
  return std::string("environment: ") + what();
}

}  // namespace taa
