// What a case gives the reference pass, as one string: the part of a reference frame's cache
// key (api/reference_cache.h) that comes from the case file. The renderer adds each frame's
// own inputs (uniforms, draws, shadow cascades), so settings that reach the reference only
// through the frame state (camera, script, jitter) are left out here; so are the settings the
// reference pass never reads (the resolve, post passes, checks, the report).
#pragma once

#include <string>

#include "api/device.h"
#include "api/render_options.h"
#include "spec/checked_case.h"

namespace taa::run {

// The case's resolved settings less the ones above, and the case's folder (files named in the
// case are relative to it; within one run a path names one content).
std::string referenceKey(const spec::CaseSpec& spec);

// Everything a case's reference frames are a function of besides the frame's own bytes and the
// reference shaders' SPIR-V (both added by ReferencePass::frameKey): within one run the path
// of a file vouches for its bytes and one device and executable render, across runs (the
// references kept on disk, api/reference_store.h) they do not. One struct so that a test
// changes each part in turn and sees another key.
struct ReferenceKeyParts {
  std::string settings;     // referenceKey(spec): the case's folder and reference settings
  std::string inputFiles;   // cases::referencedFilesSha256: scene, buffers, images, tracks
  std::string environment;  // golden::Environment fingerprint: device, driver, CPU level
  std::string build;        // the executable's build identity: the C++ that records the pass
  // The parts as RenderOptions::referenceKey.
  std::string joined() const;
};

ReferenceKeyParts referenceKeyParts(const spec::CaseSpec& spec, const DeviceIdentity& device);

// Points `options` (a lane capturing the reference) at `cache` under the case's key; no-op when
// `cache` is null.
void shareReferences(RenderOptions& options, ReferenceCache* cache, const spec::CaseSpec& spec,
                     const DeviceIdentity& device);

}  // namespace taa::run
