#include "vk/pipeline_cache.h"

#include <cassert>

#include "vk/pipeline.h"

namespace taa::vk {

std::shared_ptr<const PipelineObjects> PipelineCache::get(
    const std::string& key, const std::function<std::shared_ptr<const PipelineObjects>()>& make) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (auto it = entries_.find(key); it != entries_.end()) {
      recent_.splice(recent_.begin(), recent_, it->second.recent);
      ++stats_.reused;
      return it->second.objects;
    }
  }
  auto made = make();
  std::lock_guard<std::mutex> lock(mutex_);
  if (auto it = entries_.find(key); it != entries_.end()) {
    ++stats_.reused;  // another thread made it meanwhile; ours goes when `made` does
    return it->second.objects;
  }
  ++stats_.created;
  recent_.push_front(key);
  entries_.emplace(key, Entry{made, recent_.begin()});
  evictUnused();
  return made;
}

void PipelineCache::evictUnused() {
  size_t unused = 0;
  for (const auto& [key, e] : entries_)
    if (e.objects.use_count() == 1) ++unused;
  for (auto it = recent_.end(); unused > keepUnused_ && it != recent_.begin();) {
    --it;
    auto entry = entries_.find(*it);
    assert(entry != entries_.end());  // recent_ lists exactly the keys of entries_
    if (entry->second.objects.use_count() != 1) continue;
    entries_.erase(entry);
    it = recent_.erase(it);
    --unused;
  }
}

PipelineCacheStats PipelineCache::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

size_t PipelineCache::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

void PipelineCache::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  entries_.clear();
  recent_.clear();
}

}  // namespace taa::vk
