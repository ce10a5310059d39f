#include "api/reference_cache.h"

#include <stdexcept>
#include <utility>

#include "api/reference_store.h"

namespace taa {

namespace {
size_t imageBytes(const Image& image) { return image.data.size() * sizeof(float); }
}  // namespace

std::shared_ptr<const Image> ReferenceCache::find(const std::string& key) {
  return findOrClaim(key).image;  // a miss's claim goes at once: nothing renders it here
}

void ReferenceCache::insert(const std::string& key, Image image) {
  if (store_) store_->save(key, image);
  std::lock_guard<std::mutex> lock(mutex_);
  ++stats_.rendered;
  keep(key, std::make_shared<const Image>(std::move(image)));
}

ReferenceCache::Lookup ReferenceCache::findOrClaim(const std::string& key) {
  // A cache that keeps nothing (--no-reference-cache) has nothing to wait for: every asker
  // renders, as told.
  const bool keeps = maxBytes_ > 0 || store_;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    if (keeps && claimed_.count(key)) {
      ++waiting_;
      claimsChanged_.wait(lock, [&] { return !claimed_.count(key); });
      --waiting_;
    }
    const auto it = entries_.find(key);
    if (it != entries_.end()) {
      recent_.splice(recent_.begin(), recent_, it->second.recent);
      ++stats_.reused;
      return {it->second.image, {}};
    }
    if (keeps) claimed_.insert(key);  // held while the store is read too
  }
  Claim claim(this, key);
  // The file is read outside the lock: other keys' look-ups need not wait for it.
  if (store_) {
    if (std::optional<Image> loaded = store_->load(key)) {
      auto image = std::make_shared<const Image>(std::move(*loaded));
      {
        std::lock_guard<std::mutex> lock(mutex_);
        ++stats_.fromDisk;
        keep(key, image);
      }
      return {image, {}};  // `claim` goes, waking the waiters: the image is in memory now
    }
  }
  return {nullptr, std::move(claim)};
}

size_t ReferenceCache::waiting() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return waiting_;
}

void ReferenceCache::unclaim(const std::string& key) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    claimed_.erase(key);
  }
  claimsChanged_.notify_all();
}

ReferenceCache::Claim& ReferenceCache::Claim::operator=(Claim&& other) noexcept {
  if (this != &other) {
    release();
    cache_ = std::exchange(other.cache_, nullptr);
    key_ = std::move(other.key_);
  }
  return *this;
}

void ReferenceCache::Claim::fulfil(Image image) {
  if (!cache_) throw std::logic_error("ReferenceCache::Claim::fulfil: no claim");
  cache_->insert(key_, std::move(image));
  release();
}

void ReferenceCache::Claim::release() {
  if (cache_) std::exchange(cache_, nullptr)->unclaim(key_);
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
