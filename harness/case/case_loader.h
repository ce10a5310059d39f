// Case files: JSON in, a fully resolved CheckedCase (the renderer's CaseSpec and the
// harness's checks) out, or a CaseError listing every
// problem with its file, key path and fix.
#pragma once

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <set>
#include <string>

#include "spec/checked_case.h"

namespace taa::cases {

struct LoadedCase {
  spec::CheckedCase spec;
  std::set<std::string> present;  // key paths the file sets; the rest are defaults
  // Of the file's bytes and of every file it references (scene, mover models, tracks),
  // for stale-golden detection.
  std::string sha256;
  // report.ab: the B side's case JSON (the file with the preset merged in), "" without A/B.
  std::string abCase;
};

LoadedCase loadCase(const std::filesystem::path& file);

// SHA-256 over the bytes of every file the case reads other than the case file and a user's
// shader: the scene and mover glTFs with the buffers and images they name, the tracks, the
// still image. A reference kept across runs (run/reference_key.h) is a function of these; an
// edit of the case's resolve settings or shader leaves the digest as it was.
std::string referencedFilesSha256(const spec::CaseSpec& spec);

// A JSON file a command reads beside its cases (a case to patch, a presets or lanes file):
// bounded in size and nesting before parsing, parse errors quoting none of its bytes.
// Throws CaseError naming the file.
nlohmann::json readJsonFile(const std::filesystem::path& file);

// Parses JSON text as if read from `file` (tests and in-memory cases use this).
LoadedCase parseCase(const std::string& text, const std::filesystem::path& file);

// The same for a lane the harness builds: taa.shader relative to `shaderRoot` rather than
// to the case's folder (its includes must stay inside that folder; a scorecard's lane names
// a shader on the command line, a sweep's preset one beside its presets file), and a case
// the shader lacks a capability for left to the lane's runner to skip.
struct LaneParse {
  std::filesystem::path shaderRoot;  // taa.shader_root; empty: the case's folder
  bool capabilitiesUnchecked = false;  // taa.shader_capabilities_unchecked
};
LoadedCase parseCase(const std::string& text, const std::filesystem::path& file,
                     const LaneParse& lane);

// Every value in force, as JSON (taa-harness validate --print).
nlohmann::json resolvedJson(const spec::CheckedCase& spec);

// One row per setting of the case format (taa-harness techniques --json).
nlohmann::json settingsSchema();

}  // namespace taa::cases
