#include <iostream>

#include "cli/commands.h"
#include "cli/exit_codes.h"

namespace taa::cli {

int cmdRender(const Args&) {
  std::cerr << "render: not built yet\n";
  return kEnvironment;
}

}  // namespace taa::cli
