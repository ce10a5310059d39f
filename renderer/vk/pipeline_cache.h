// Pipelines made once per context: a pass asks for a pipeline by everything that shapes it
// (its SPIR-V, specialization constants and fixed-function state), and a second renderer on
// the same context (the next case of a run) gets the one already compiled instead of making
// and compiling another. lavapipe's VkPipelineCache keeps nothing between pipelines, so the
// cache holds the pipelines themselves.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

namespace taa::vk {

struct PipelineObjects;

struct PipelineCacheStats {
  size_t created = 0;  // pipelines compiled
  size_t reused = 0;   // requests answered with one compiled before
};

class PipelineCache {
 public:
  // Pipelines no one holds are kept up to `keepUnused`, least recently asked for dropped
  // first: a run of many cases with different settings keeps flat memory.
  explicit PipelineCache(size_t keepUnused = 256) : keepUnused_(keepUnused) {}

  // The pipeline made for `key`, else the one `make` makes (then kept under `key`). `make` runs
  // outside the lock; two threads asking for a new key at once may both make it, and the first
  // kept wins.
  std::shared_ptr<const PipelineObjects> get(
      const std::string& key, const std::function<std::shared_ptr<const PipelineObjects>()>& make);

  PipelineCacheStats stats() const;
  size_t size() const;
  // Drops every pipeline the cache holds (the context does, before its device goes).
  void clear();

 private:
  struct Entry {
    std::shared_ptr<const PipelineObjects> objects;
    std::list<std::string>::iterator recent;
  };
  void evictUnused();  // with mutex_ held

  size_t keepUnused_;
  mutable std::mutex mutex_;
  std::unordered_map<std::string, Entry> entries_;
  std::list<std::string> recent_;  // most recently asked for first
  PipelineCacheStats stats_;
};

}  // namespace taa::vk
