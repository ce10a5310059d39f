#include "api/reference_cache.h"

#include "api/reference_store.h"

namespace taa {

namespace {
size_t imageBytes(const Image& image) { return image.data.size() * sizeof(float); }
}  // namespace

std::shared_ptr<const Image> ReferenceCache::find(const std::string& key) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = entries_.find(key);
    if (it != entries_.end()) {
      recent_.splice(recent_.begin(), recent_, it->second.recent);
      ++stats_.reused;
      return it->second.image;
    }
  }
  if (!store_) return nullptr;
  // Outside the lock: the other workers' look-ups need not wait for this file.
  std::optional<Image> loaded = store_->load(key);
  if (!loaded) return nullptr;
  auto image = std::make_shared<const Image>(std::move(*loaded));
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.fromDisk;
  keep(key, image);
  return image;
}

void ReferenceCache::insert(const std::string& key, Image image) {
  if (store_) store_->save(key, image);
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.rendered;
  keep(key, std::make_shared<const Image>(std::move(image)));
}

void ReferenceCache::keep(const std::string& key, std::shared_ptr<const Image> image) {
  if (entries_.count(key) || imageBytes(*image) > maxBytes_) return;
  stats_.bytes += imageBytes(*image);
  recent_.push_front(key);
  entries_.emplace(key, Entry{std::move(image), recent_.begin()});
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
