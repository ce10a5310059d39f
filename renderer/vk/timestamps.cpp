#include "vk/timestamps.h"

#include "vk/check.h"
#include "vk/context.h"

namespace taa::vk {

GpuTimer::GpuTimer(Context& ctx, uint32_t maxScopes) : ctx_(ctx), capacity_(maxScopes * 2) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = capacity_;
  VK_CHECK(vkCreateQueryPool(ctx.device(), &info, nullptr, &pool_));
  reset();
}

GpuTimer::~GpuTimer() { vkDestroyQueryPool(ctx_.device(), pool_, nullptr); }

void GpuTimer::reset() {
  vkResetQueryPool(ctx_.device(), pool_, 0, capacity_);
  names_.clear();
  used_ = 0;
  open_ = false;
}

void GpuTimer::begin(VkCommandBuffer cmd, const std::string& name) {
  if (open_) throw std::logic_error("GpuTimer: scope '" + name + "' opened inside '" + names_.back() + "'");
  if (used_ + 2 > capacity_) throw std::logic_error("GpuTimer: more than " + std::to_string(capacity_ / 2) + " scopes");
  names_.push_back(name);
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, used_++);
  open_ = true;
}

void GpuTimer::end(VkCommandBuffer cmd) {
  if (!open_) throw std::logic_error("GpuTimer: end() without begin()");
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, used_++);
  open_ = false;
}

std::vector<std::pair<std::string, double>> GpuTimer::read() {
  std::vector<std::pair<std::string, double>> out;
  if (used_ == 0) return out;
  std::vector<uint64_t> ticks(used_);
  VK_CHECK(vkGetQueryPoolResults(ctx_.device(), pool_, 0, used_, ticks.size() * sizeof(uint64_t), ticks.data(),
                                 sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  const double msPerTick = double(ctx_.info().timestampPeriodNs) * 1e-6;
  for (size_t i = 0; i < names_.size(); ++i)
    out.emplace_back(names_[i], double(ticks[2 * i + 1] - ticks[2 * i]) * msPerTick);
  return out;
}

}  // namespace taa::vk
