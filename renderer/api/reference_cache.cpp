#include "api/reference_cache.h"

namespace taa {

namespace {
size_t imageBytes(const Image& image) { return image.data.size() * sizeof(float); }
}  // namespace

std::shared_ptr<const Image> ReferenceCache::find(const std::string& key) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = entries_.find(key);
  if (it == entries_.end()) return nullptr;
  recent_.splice(recent_.begin(), recent_, it->second.recent);
  ++stats_.reused;
  return it->second.image;
}

void ReferenceCache::insert(const std::string& key, Image image) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.rendered;
  if (entries_.count(key) || imageBytes(image) > maxBytes_) return;
  stats_.bytes += imageBytes(image);
  recent_.push_front(key);
  entries_.emplace(key, Entry{std::make_shared<const Image>(std::move(image)), recent_.begin()});
  while (stats_.bytes > maxBytes_) {
    const auto oldest = entries_.find(recent_.back());
    stats_.bytes -= imageBytes(*oldest->second.image);
    entries_.erase(oldest);
    recent_.pop_back();
  }
}

std::vector<std::string> ReferenceCache::keys() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return {recent_.begin(), recent_.end()};
}

ReferenceCacheStats ReferenceCache::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

}  // namespace taa
