// Reference frames rendered once per run: the supersampled ground truth of a frame is a
// function of what the reference pass draws (the scene and shading settings its case gives,
// which the caller names in RenderOptions::referenceKey) and of that frame's bytes (every
// sub-sample's uniforms, the instances, deformed vertices and draws, the shadow cascades).
// Cases sharing a scene, camera and reference settings, and the frames of a still scene,
// then pay for one reference render. A hit is bit-identical to a render: it is the bytes a
// render of the same inputs read back.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/image.h"

namespace taa {

class ReferenceStore;

struct ReferenceCacheStats {
  size_t rendered = 0;  // references rendered (misses)
  size_t fromDisk = 0;  // references read from the store (an earlier process rendered them)
  size_t reused = 0;    // references taken from memory
  size_t bytes = 0;     // held now
};

// What a process keeps of references in memory unless told otherwise (run, score, sweep).
inline constexpr size_t kDefaultReferenceMemoryBytes = size_t(128) << 20;

class ReferenceCache {
 public:
  // Holds at most `maxBytes` of images, dropping the least recently used first: memory stays
  // flat however many cases a run has.
  // A miss in memory asks `store` (api/reference_store.h), when given, and a render is written
  // to it.
  explicit ReferenceCache(size_t maxBytes = kDefaultReferenceMemoryBytes, ReferenceStore* store = nullptr)
      : maxBytes_(maxBytes), store_(store) {}

  // The image kept under `key`, in memory or in the store, if any (findOrClaim without the
  // claim: for callers that render nothing on a miss).
  std::shared_ptr<const Image> find(const std::string& key);
  void insert(const std::string& key, Image image);

  // A miss's promise to render its key. Until it is fulfilled or dropped, other threads that
  // ask for the key wait (two workers starting cases with one reference rendered it twice);
  // dropped unfulfilled (the frame threw, or read no reference), it lets one of them render.
  class Claim {
   public:
    Claim() = default;
    Claim(Claim&& other) noexcept { *this = std::move(other); }
    Claim& operator=(Claim&& other) noexcept;
    Claim(const Claim&) = delete;
    Claim& operator=(const Claim&) = delete;
    ~Claim() { release(); }
    explicit operator bool() const { return cache_ != nullptr; }
    void fulfil(Image image);  // insert(key, image), then wake the waiters

   private:
    friend class ReferenceCache;
    Claim(ReferenceCache* cache, std::string key) : cache_(cache), key_(std::move(key)) {}
    void release();
    ReferenceCache* cache_ = nullptr;
    std::string key_;
  };
  struct Lookup {
    std::shared_ptr<const Image> image;  // found (in memory or the store), or
    Claim claim;                         // this caller renders it
  };
  // The image, as find() gives it, or on a miss a claim to render it; a key another thread has
  // claimed is waited for.
  // A thread must not hold a claim while it asks for another key (the renderer holds one for
  // the frame it records).
  Lookup findOrClaim(const std::string& key);
  // Threads waiting in findOrClaim now (for tests).
  size_t waiting() const;
  ReferenceCacheStats stats() const;
  // The keys held, most recently used first (for tests that compare two caches' images).
  std::vector<std::string> keys() const;

 private:
  struct Entry {
    std::shared_ptr<const Image> image;
    std::list<std::string>::iterator recent;
  };
  void keep(const std::string& key, std::shared_ptr<const Image> image);  // under mutex_

  void unclaim(const std::string& key);

  size_t maxBytes_;
  ReferenceStore* store_;
  mutable std::mutex mutex_;
  std::condition_variable claimsChanged_;
  std::unordered_set<std::string> claimed_;  // keys a thread is rendering
  size_t waiting_ = 0;
  std::unordered_map<std::string, Entry> entries_;
  std::list<std::string> recent_;  // most recently used first
  ReferenceCacheStats stats_;
};

}  // namespace taa
