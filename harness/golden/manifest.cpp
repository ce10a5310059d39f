#include "golden/manifest.h"

#include <climits>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

#include "case/json_number.h"
#include "core/input_file.h"
#include "core/json_guard.h"
#include "golden/case_owner.h"

namespace taa::golden {

namespace {
std::string shownFolder(const std::filesystem::path& dir) {
  std::error_code ec;
  const auto rel = std::filesystem::relative(dir, std::filesystem::current_path(ec), ec);
  const bool below = !ec && !rel.empty() && *rel.begin() != "..";
  return (below ? rel : dir).string();
}
}  // namespace

std::string restoreHint(const std::filesystem::path& dir) {
  return "restore it with `git checkout -- " + shownFolder(dir) +
         "` (or re-bless the case with a reason)";
}

std::string manifestRestoreHint(const std::filesystem::path& dir) {
  const std::string shown = shownFolder(dir);
  return "restore it with `git checkout -- " + shown + "` (a bless continues its history, so it " +
         "needs it readable; to start the case's history over, delete " + shown +
         " and bless the case with a reason)";
}

std::string frameBase(int frame) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "frame_%04d", frame);
  return buf;
}

namespace {
nlohmann::json blessJson(const BlessRecord& b) {
  return {{"date", b.date}, {"commit", b.commit}, {"reason", b.reason}};
}
BlessRecord blessFrom(const nlohmann::json& j) {
  return {j.value("date", ""), j.value("commit", ""), j.value("reason", "")};
}

// A long static case renders thousands of identical frames; a run of equal entries is stored once
// as {"repeat": value, "frames": n} so a 10,000-frame golden stays a few kilobytes.
constexpr size_t kMinManifestRun = 3;
constexpr size_t kMaxManifestFrames = size_t(1) << 24;

nlohmann::json runLengthJson(const std::vector<std::string>& values) {
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < values.size();) {
    size_t end = i + 1;
    while (end < values.size() && values[end] == values[i]) ++end;
    if (end - i >= kMinManifestRun)
      out.push_back({{"repeat", values[i]}, {"frames", end - i}});
    else
      for (size_t k = i; k < end; ++k) out.push_back(values[k]);
    i = end;
  }
  return out;
}

std::vector<std::string> runLengthValues(const nlohmann::json& list, const char* key) {
  std::vector<std::string> values;
  for (const auto& entry : list) {
    if (entry.is_string()) {
      values.push_back(entry.get<std::string>());
    } else {
      const auto frames = entry.at("frames").get<uint64_t>();
      if (frames == 0 || frames > kMaxManifestFrames - values.size())
        throw std::out_of_range(std::string(key) + ": a repeat of " + std::to_string(frames) +
                                " frames is outside 1.." + std::to_string(kMaxManifestFrames) +
                                " in all");
      values.insert(values.end(), size_t(frames), entry.at("repeat").get<std::string>());
    }
  }
  return values;
}

nlohmann::json positiveJson(const Positive& p, const Manifest& m) {
  nlohmann::json j = {{"environment", p.environment.toJson()},
                      {"date", p.bless.date},
                      {"renderer_commit", p.bless.commit},
                      {"reason", p.bless.reason}};
  if (p.sequence == m.sequence && p.signatures == m.signatures) {
    j["same_frames_as_primary"] = true;
  } else {
    j["frame_sha256"] = runLengthJson(p.sequence);
    j["frame_signatures"] = runLengthJson(p.signatures);
  }
  return j;
}

Positive positiveFrom(const nlohmann::json& j, const Manifest& m) {
  Positive p;
  p.environment = Environment::fromJson(j.at("environment"));
  p.bless = {j.at("date").get<std::string>(), j.at("renderer_commit").get<std::string>(),
             j.at("reason").get<std::string>()};
  if (j.value("same_frames_as_primary", false)) {
    p.sequence = m.sequence;
    p.signatures = m.signatures;
  } else {
    p.sequence = runLengthValues(j.at("frame_sha256"), "other_environments.frame_sha256");
    p.signatures = runLengthValues(j.at("frame_signatures"), "other_environments.frame_signatures");
  }
  if (p.sequence.empty() || p.signatures.size() != p.sequence.size())
    throw std::out_of_range("other_environments: " + p.environment.fingerprint() + " lists " +
                            std::to_string(p.sequence.size()) + " frame hashes and " +
                            std::to_string(p.signatures.size()) + " signatures");
  return p;
}
}  // namespace

std::vector<Positive> Manifest::positives() const {
  std::vector<Positive> all{{environment, bless, sequence, signatures}};
  all.insert(all.end(), others.begin(), others.end());
  return all;
}

std::optional<Positive> Manifest::positiveFor(const std::string& fingerprint) const {
  for (auto& p : positives())
    if (p.environment.fingerprint() == fingerprint) return p;
  return std::nullopt;
}

nlohmann::json Manifest::toJson() const {
  nlohmann::json j = {{"case", caseName},
                      {"case_sha256", caseSha256},
                      {"environment", environment.toJson()},
                      {"date", bless.date},
                      {"renderer_commit", bless.commit},
                      {"reason", bless.reason},
                      {"history", nlohmann::json::array()},
                      {"frames", nlohmann::json::array()},
                      {"frame_sha256", runLengthJson(sequence)},
                      {"frame_signatures", runLengthJson(signatures)}};
  if (!caseFile.empty()) j["case_file"] = caseFile;
  for (const auto& h : history) j["history"].push_back(blessJson(h));
  if (!others.empty()) {
    j["other_environments"] = nlohmann::json::array();
    for (const auto& p : others) j["other_environments"].push_back(positiveJson(p, *this));
  }
  for (const auto& f : frames)
    j["frames"].push_back({{"frame", f.frame},
                           {"file", f.file},
                           {"sha256", f.sha256},
                           {"width", f.width},
                           {"height", f.height}});
  return j;
}

namespace {

// A frame number or size as written, at least LOW (case/json_number.h says why not get<int>).
int wholeNumber(const nlohmann::json& frame, const char* key, int low,
                const std::filesystem::path& where) {
  const nlohmann::json& v = frame.at(key);
  int64_t n = 0;
  if (!jsonWholeIn(v, low, INT_MAX, n))
    throw GoldenError(where.string() + ": frames[]." + key + " is " + v.dump() +
                      ", not a whole number from " + std::to_string(low) + " to " +
                      std::to_string(INT_MAX) + "; " + manifestRestoreHint(where.parent_path()));
  return int(n);
}

}  // namespace

Manifest Manifest::fromJson(const nlohmann::json& j, const std::filesystem::path& where) {
  Manifest m;
  try {
    m.caseName = j.at("case").get<std::string>();
    m.caseSha256 = j.at("case_sha256").get<std::string>();
    if (j.contains("case_file")) {
      m.caseFile = j.at("case_file").get<std::string>();
      if (!validCaseFileLabel(m.caseFile))
        throw GoldenError(where.string() + ": case_file is not a case's folder and file name (" +
                          std::to_string(m.caseFile.size()) + " bytes); " +
                          manifestRestoreHint(where.parent_path()));
    }
    m.environment = Environment::fromJson(j.at("environment"));
    m.bless = {j.at("date").get<std::string>(), j.at("renderer_commit").get<std::string>(),
               j.at("reason").get<std::string>()};
    for (const auto& h : j.value("history", nlohmann::json::array()))
      m.history.push_back(blessFrom(h));
    for (const auto& f : j.at("frames"))
      m.frames.push_back({wholeNumber(f, "frame", 0, where), f.at("file").get<std::string>(),
                          f.at("sha256").get<std::string>(), wholeNumber(f, "width", 1, where),
                          wholeNumber(f, "height", 1, where)});
    // Absent in manifests blessed before every frame was hashed; the runner reports those.
    if (j.contains("frame_sha256"))
      m.sequence = runLengthValues(j.at("frame_sha256"), "frame_sha256");
    if (j.contains("frame_signatures"))
      m.signatures = runLengthValues(j.at("frame_signatures"), "frame_signatures");
    for (const auto& o : j.value("other_environments", nlohmann::json::array()))
      m.others.push_back(positiveFrom(o, m));
  } catch (const nlohmann::json::exception& e) {
    throw GoldenError(where.string() + ": malformed golden manifest (" + e.what() + "); " +
                      manifestRestoreHint(where.parent_path()));
  } catch (const std::out_of_range& e) {
    throw GoldenError(where.string() + ": malformed golden manifest (" + e.what() + "); " +
                      manifestRestoreHint(where.parent_path()));
  }
  if (!m.signatures.empty() && m.signatures.size() != m.sequence.size())
    throw GoldenError(where.string() + ": frame_signatures lists " +
                      std::to_string(m.signatures.size()) + " frames, frame_sha256 " +
                      std::to_string(m.sequence.size()) + "; " +
                      manifestRestoreHint(where.parent_path()));
  std::set<std::string> fingerprints;
  for (const auto& p : m.positives())
    if (!fingerprints.insert(p.environment.fingerprint()).second)
      throw GoldenError(where.string() + ": two positives for the environment '" +
                        p.environment.fingerprint() + "'; " +
                        manifestRestoreHint(where.parent_path()));
  for (const auto& f : m.frames)
    if (!m.sequence.empty() && (f.frame < 0 || size_t(f.frame) >= m.sequence.size() ||
                                m.sequence[size_t(f.frame)] != f.sha256))
      throw GoldenError(where.string() + ": frame " + std::to_string(f.frame) +
                        "'s sha256 disagrees with frame_sha256 (the list of every frame's hash); " +
                        manifestRestoreHint(where.parent_path()));
  return m;
}

const GoldenFrame* Manifest::find(int frame) const {
  for (const auto& f : frames)
    if (f.frame == frame) return &f;
  return nullptr;
}

Manifest readManifest(const std::filesystem::path& file) {
  const std::string hint = manifestRestoreHint(file.parent_path());
  std::string text;
  try {
    text = readInputFile(file, kMaxCaseFileBytes);
  } catch (const InputFileMissing&) {
    // With no manifest at all, a bless starts the set afresh (as cmd_bless checks: exists()); a
    // manifest that is there but unreadable it refuses to replace. A path that cannot be looked
    // at (a folder without search permission) is not "missing": readInputFile names its error.
    throw GoldenError(file.string() + ": missing (the golden manifest); " +
                      restoreHint(file.parent_path()));
  } catch (const InputFileError& e) {
    throw GoldenError(std::string(e.what()) + " (the golden manifest); " + hint);
  }
  if (const std::string problem = jsonStructureProblem(text); !problem.empty())
    throw GoldenError(file.string() + ": " + problem + "; " + hint);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw GoldenError(file.string() + ": not valid JSON (" + jsonErrorWithoutContent(e.what()) +
                      "); " + hint);
  }
  return Manifest::fromJson(j, file);
}

}  // namespace taa::golden
