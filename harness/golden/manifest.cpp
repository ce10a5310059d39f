#include "golden/manifest.h"

#include <sstream>
#include <stdexcept>

#include "core/input_file.h"
#include "core/json_guard.h"

namespace taa::golden {

namespace {
nlohmann::json blessJson(const BlessRecord& b) { return {{"date", b.date}, {"commit", b.commit}, {"reason", b.reason}}; }
BlessRecord blessFrom(const nlohmann::json& j) {
  return {j.value("date", ""), j.value("commit", ""), j.value("reason", "")};
}
}  // namespace

nlohmann::json Manifest::toJson() const {
  nlohmann::json j = {{"case", caseName},
                      {"case_sha256", caseSha256},
                      {"environment", environment.toJson()},
                      {"date", bless.date},
                      {"renderer_commit", bless.commit},
                      {"reason", bless.reason},
                      {"history", nlohmann::json::array()},
                      {"frames", nlohmann::json::array()}};
  for (const auto& h : history) j["history"].push_back(blessJson(h));
  for (const auto& f : frames)
    j["frames"].push_back(
        {{"frame", f.frame}, {"file", f.file}, {"sha256", f.sha256}, {"width", f.width}, {"height", f.height}});
  return j;
}

Manifest Manifest::fromJson(const nlohmann::json& j, const std::filesystem::path& where) {
  try {
    Manifest m;
    m.caseName = j.at("case").get<std::string>();
    m.caseSha256 = j.at("case_sha256").get<std::string>();
    m.environment = Environment::fromJson(j.at("environment"));
    m.bless = {j.at("date").get<std::string>(), j.at("renderer_commit").get<std::string>(),
               j.at("reason").get<std::string>()};
    for (const auto& h : j.value("history", nlohmann::json::array())) m.history.push_back(blessFrom(h));
    for (const auto& f : j.at("frames"))
      m.frames.push_back({f.at("frame").get<int>(), f.at("file").get<std::string>(), f.at("sha256").get<std::string>(),
                          f.at("width").get<int>(), f.at("height").get<int>()});
    return m;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(where.string() + ": malformed golden manifest (" + e.what() +
                             "); restore it from git or re-bless the case");
  }
}

const GoldenFrame* Manifest::find(int frame) const {
  for (const auto& f : frames)
    if (f.frame == frame) return &f;
  return nullptr;
}

Manifest readManifest(const std::filesystem::path& file) {
  std::string text;
  try {
    text = readInputFile(file, kMaxCaseFileBytes);
  } catch (const InputFileError& e) {
    throw std::runtime_error(std::string(e.what()) + " (the golden manifest); restore it from git or re-bless");
  }
  if (const std::string problem = jsonStructureProblem(text); !problem.empty())
    throw std::runtime_error(file.string() + ": " + problem + "; restore it from git or re-bless");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": not valid JSON (" + e.what() + "); restore it from git or re-bless");
  }
  return Manifest::fromJson(j, file);
}

}  // namespace taa::golden
