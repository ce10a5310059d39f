#include "case/validate_tracks.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>

#include "api/tracks.h"
#include "case/case_error.h"
#include "case/case_validate.h"

namespace taa::cases {

namespace {

using TrackProblems = std::vector<std::pair<std::string, std::string>>;

std::string extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// True when the file sets `key` or anything below it.
bool setsBelow(const std::set<std::string>& present, const std::string& key) {
  const auto it = present.lower_bound(key);
  if (it == present.end()) return false;
  return *it == key || it->rfind(key + ".", 0) == 0 || it->rfind(key + "[", 0) == 0;
}

void trackPath(TrackProblems& p, const std::string& key, const std::string& value,
               const std::vector<std::string>& extensions) {
  if (const std::string why = assetPathProblem(value); !why.empty()) p.emplace_back(key, why);
  const std::string ext = extension(value);
  if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
    std::string list;
    for (const auto& e : extensions) list += (list.empty() ? "" : ", ") + e;
    p.emplace_back(key, "'" + value + "' is not a track file; give a " + list + " file");
  }
}

void cameraRules(TrackProblems& p, const spec::CameraSpec& cam, const std::set<std::string>& present) {
  if (cam.track.empty()) {
    for (const char* key : {"camera.track_camera", "camera.track_time_offset_s"})
      if (present.count(key))
        p.emplace_back(key, "set but camera.track is not; set it or remove this");
    return;
  }
  trackPath(p, "camera.track", cam.track, {".json", ".csv", ".gltf", ".glb"});
  const std::string ext = extension(cam.track);
  if (present.count("camera.track_camera") && ext != ".gltf" && ext != ".glb")
    p.emplace_back(
        "camera.track_camera",
        "names a glTF camera node, but camera.track is not a .gltf/.glb file; remove it");
  for (const char* key : {"camera.position", "camera.target", "camera.path", "camera.rotate",
                          "camera.bob", "camera.strafe", "camera.cuts"})
    if (setsBelow(present, key))
      p.emplace_back(key,
                     "camera.track replaces it (the track gives the pose and its cuts); "
                     "remove it, or remove camera.track");
}

void moverRules(TrackProblems& p, const std::vector<spec::MoverSpec>& movers,
                const std::set<std::string>& present) {
  for (size_t i = 0; i < movers.size(); ++i) {
    const std::string m = "movers[" + std::to_string(i) + "]";
    if (movers[i].track.empty()) {
      if (present.count(m + ".track_time_offset_s"))
        p.emplace_back(m + ".track_time_offset_s",
                       "set but " + m + ".track is not; set it or remove this");
      continue;
    }
    trackPath(p, m + ".track", movers[i].track, {".json", ".csv"});
    for (const char* key : {"start", "end", "speed", "speed_unit", "repeat", "rotation_axis",
                            "rotation_speed_deg", "continuous_rotation", "size"})
      if (present.count(m + "." + key))
        p.emplace_back(m + "." + key,
                       m + ".track replaces it (the track gives the whole "
                           "transform, scale included); remove it, or remove the track");
  }
}

}  // namespace

std::vector<std::pair<std::string, std::string>> trackProblems(
    const spec::CaseSpec& spec, const std::set<std::string>& present) {
  TrackProblems p;
  cameraRules(p, spec.camera, present);
  moverRules(p, spec.movers, present);
  return p;
}

void loadCaseTracks(spec::CaseSpec& spec, const std::set<std::string>& present) {
  spec.tracks.reset();
  CaseTracks loaded;
  try {
    loaded = readCaseTracks(spec);
  } catch (const script::TrackError& e) {
    throw CaseError({e.what()});
  }
  std::vector<std::string> problems;
  for (const std::string& key : loaded.lensKeys)
    if (present.count("camera." + key))
      problems.push_back(spec.file.string() + ": camera." + key + ": the camera track carries " +
                         key + " for every frame, which replaces this setting; remove it");
  if (!problems.empty()) throw CaseError(problems);
  spec.tracks = std::move(loaded.tracks);
}

}  // namespace taa::cases
