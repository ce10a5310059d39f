// Reference frames rendered once per run: the supersampled ground truth of a frame is a
// function of what the reference pass draws (the scene and shading settings its case gives,
// which the caller names in RenderOptions::referenceKey) and of that frame's bytes (every
// sub-sample's uniforms, the instances, deformed vertices and draws, the shadow cascades).
// Cases sharing a scene, camera and reference settings, and the frames of a still scene,
// then pay for one reference render. A hit is bit-identical to a render: it is the bytes a
// render of the same inputs read back.
#pragma once

#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/image.h"

namespace taa {

struct ReferenceCacheStats {
  size_t rendered = 0;  // references rendered (misses)
  size_t reused = 0;    // references taken from the cache
  size_t bytes = 0;     // held now
};

class ReferenceCache {
 public:
  // Holds at most `maxBytes` of images, dropping the least recently used first: memory stays
  // flat however many cases a run has.
  explicit ReferenceCache(size_t maxBytes = size_t(128) << 20) : maxBytes_(maxBytes) {}

  // The image kept under `key`, if any.
  std::shared_ptr<const Image> find(const std::string& key);
  void insert(const std::string& key, Image image);
  ReferenceCacheStats stats() const;
  // The keys held, most recently used first (for tests that compare two caches' images).
  std::vector<std::string> keys() const;

 private:
  struct Entry {
    std::shared_ptr<const Image> image;
    std::list<std::string>::iterator recent;
  };
  size_t maxBytes_;
  mutable std::mutex mutex_;
  std::unordered_map<std::string, Entry> entries_;
  std::list<std::string> recent_;  // most recently used first
  ReferenceCacheStats stats_;
};

}  // namespace taa
