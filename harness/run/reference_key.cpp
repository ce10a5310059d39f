#include "run/reference_key.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "case/case_loader.h"
#include "golden/environment.h"
#include "run/build_identity.h"

namespace taa::run {

namespace {

// Sections and keys the reference pass does not read, or reads only through the frame state
// its frame key hashes. tests/harness/reference_key_test.cpp renders every setting of these
// with the cache off and checks the reference bits do not move.
const char* const kNotReferenceInputs[] = {
    "description", "checks", "report", "output",
    "taa",         // the resolve (and taa.moving)
    "adaptive",    // a follower of the resolve
    "post",        // motion blur before the resolve, sharpen/CAS/FXAA after it
    "inject",      // writes into the frame's colour target, not the reference's
    "jitter",      // the reference replaces the frame's jitter with its own sub-sample offsets
    "camera",      // through the frame's camera: the uniforms in the frame key
    "script",      // through the frame's time: camera, draws and uniforms in the frame key
    "/render/msaa", "/render/scale_schedule", "/render/upsample",  // the frame's raster only
    "/debug/output", "/debug/channels", "/debug/scale",            // applied to the output
    "/tscmaa/blurriness", "/tscmaa/edge_threshold", "/tscmaa/history_weight",
    "/tscmaa/non_dominant_edge_removal", "/tscmaa/taa_share",      // TSCMAA's resolve
};

}  // namespace

std::string referenceKey(const spec::CaseSpec& spec) {
  spec::CheckedCase all;  // checks and report at their defaults: both are erased below
  static_cast<spec::CaseSpec&>(all) = spec;
  nlohmann::json j = cases::resolvedJson(all);
  for (const char* key : kNotReferenceInputs) {
    if (key[0] != '/') {
      j.erase(key);
      continue;
    }
    const nlohmann::json::json_pointer at(key);
    if (j.contains(at)) j[at.parent_pointer()].erase(at.back());
  }
  std::error_code ec;
  auto folder = std::filesystem::weakly_canonical(std::filesystem::absolute(spec.file).parent_path(), ec);
  return folder.string() + "\n" + j.dump();
}

std::string ReferenceKeyParts::joined() const {
  std::string out;
  for (const std::string* part : {&settings, &inputFiles, &environment, &build})
    out += std::to_string(part->size()) + ":" + *part + "\n";  // lengths delimit the parts
  return out;
}

ReferenceKeyParts referenceKeyParts(const spec::CaseSpec& spec, const DeviceIdentity& device) {
  return {referenceKey(spec), cases::referencedFilesSha256(spec),
          golden::currentEnvironment(device).fingerprint(), executableIdentity()};
}

void shareReferences(RenderOptions& options, ReferenceCache* cache, const spec::CaseSpec& spec,
                     const DeviceIdentity& device) {
  if (!cache) return;
  options.referenceCache = cache;
  options.referenceKey = referenceKeyParts(spec, device).joined();
}

}  // namespace taa::run
