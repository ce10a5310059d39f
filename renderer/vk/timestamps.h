// GPU time per pass from timestamp queries: scopes are opened and closed while
// recording, and read back after the frame's submission completed.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <utility>
#include <vector>

namespace taa::vk {

class Context;

class GpuTimer {
 public:
  GpuTimer(Context& ctx, uint32_t maxScopes = 64);
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  void reset();  // host-side reset before recording a frame
  void begin(VkCommandBuffer cmd, const std::string& name);
  void end(VkCommandBuffer cmd);
  // Milliseconds per scope in recording order; call after the work completed.
  std::vector<std::pair<std::string, double>> read();

 private:
  Context& ctx_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  uint32_t capacity_;
  std::vector<std::string> names_;
  uint32_t used_ = 0;
  bool open_ = false;
};

}  // namespace taa::vk
