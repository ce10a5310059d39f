#include "script/tracks.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <map>

#include "core/input_file.h"
#include "script/timing.h"
#include "script/track_csv.h"
#include "script/track_gltf.h"
#include "script/track_json.h"
#include "script/track_resample.h"

namespace taa::script {

namespace {

namespace fs = std::filesystem;

// Same rule as scene paths: relative, no URI, never leaving the case's folder tree.
fs::path resolve(const spec::CaseSpec& spec, const std::string& path) {
  const fs::path p(path);
  bool escapes = path.find("://") != std::string::npos || p.is_absolute() || p.has_root_name();
  for (const auto& part : p.lexically_normal()) escapes = escapes || part == "..";
  if (escapes)
    throw TrackError("'" + path +
                     "' is not a relative path inside the case's folder; move the track under "
                     "the case's folder and give its relative path");
  // The lexical rule above gives the clearer message; this one also sees symbolic links.
  try {
    containedRealPath(spec.file.parent_path(), spec.file.parent_path() / p, "the track");
  } catch (const InputFileError& e) {
    throw TrackError(e.what());
  }
  return spec.file.parent_path() / p;
}

std::string extension(const fs::path& p) {
  std::string e = p.extension().string();
  for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

std::string readText(const fs::path& file) {
  try {
    return readInputFile(file, kMaxTrackFileBytes);
  } catch (const InputFileError& e) {
    throw TrackError(e.what());
  }
}

// JSON files parsed once per load, though the camera and several movers may share one.
class JsonCache {
 public:
  const TrackFile& get(const fs::path& file) {
    auto it = files_.find(file.string());
    if (it == files_.end())
      it = files_.emplace(file.string(), parseJsonTrack(readText(file), file.string())).first;
    return it->second;
  }

 private:
  std::map<std::string, TrackFile> files_;
};

// The offset as the decimal the case file wrote (0.1, not the float 0.10000000149):
// a track recorded at offset + k / fps then lines up with the frames exactly.
double offsetSeconds(float offset) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), offset);
  return std::strtod(std::string(buf, r.ptr).c_str(), nullptr);
}

std::vector<double> frameTimes(const spec::CaseSpec& spec, double offsetS) {
  std::vector<double> times;
  for (int n = 0; n < spec.script.frames; ++n) times.push_back(offsetS + frameTime(spec.script, n));
  return times;
}

RawTrack cameraRaw(const spec::CaseSpec& spec, JsonCache& json) {
  const auto& cam = spec.camera;
  const fs::path file = resolve(spec, cam.track);
  const std::string ext = extension(file);
  if (ext == ".csv") return parseCsvTrack(readText(file), file.string(), TrackSubject::Camera);
  if (ext == ".gltf" || ext == ".glb")
    return gltfCameraTrack(file, cam.track_camera,
                           frameTimes(spec, offsetSeconds(cam.track_time_offset_s)));
  if (ext != ".json")
    throw TrackError("'" + cam.track + "' is not a .json, .csv, .gltf or .glb file");
  const TrackFile& f = json.get(file);
  if (!f.camera)
    throw TrackError(file.string() +
                     ": has no \"camera\" entry; add one or point camera.track "
                     "at a file that records the camera");
  return *f.camera;
}

RawTrack moverRaw(const spec::CaseSpec& spec, size_t i, JsonCache& json) {
  const fs::path file = resolve(spec, spec.movers[i].track);
  const std::string ext = extension(file);
  if (ext == ".csv") return parseCsvTrack(readText(file), file.string(), TrackSubject::Mover);
  if (ext != ".json")
    throw TrackError("'" + spec.movers[i].track + "' is not a .json or .csv file");
  const TrackFile& f = json.get(file);
  if (f.movers.size() <= i)
    throw TrackError(file.string() + ": has " + std::to_string(f.movers.size()) +
                     " movers, but the case's movers[" + std::to_string(i) +
                     "] replays its movers[" + std::to_string(i) +
                     "]; record that mover or use a CSV track for it");
  return f.movers[i];
}

}  // namespace

bool usesTracks(const spec::CaseSpec& spec) {
  return !spec.camera.track.empty() ||
         std::any_of(spec.movers.begin(), spec.movers.end(),
                     [](const spec::MoverSpec& m) { return !m.track.empty(); });
}

std::vector<CameraFrame> cameraTrackFrames(const RawTrack& track, const spec::CaseSpec& spec) {
  const auto& cam = spec.camera;
  std::vector<CameraFrame> out;
  const auto samples = resampleTrack(track, offsetSeconds(cam.track_time_offset_s), spec.script.fps,
                                     spec.script.frames);
  for (size_t n = 0; n < samples.size(); ++n) {
    const TrackSample& s = samples[n];
    CameraFrame f;
    f.pose.position = s.position;
    f.pose.orientation = sampleOrientation(s);
    f.fovYDeg = track.hasFov ? s.fovYDeg : cam.fov_y_deg;
    f.nearPlane = track.hasNear ? s.nearPlane : cam.near_plane;
    f.farPlane = track.hasFar ? s.farPlane : cam.far_plane;
    f.cut = s.cut;
    if (!(f.nearPlane < f.farPlane))
      throw TrackError(track.source + ": frame " + std::to_string(n) + ": near " +
                       std::to_string(f.nearPlane) + " is not below far " +
                       std::to_string(f.farPlane) + " (" +
                       (track.hasNear ? "the track's near" : "the case's camera.near") + ", " +
                       (track.hasFar ? "the track's far" : "the case's camera.far") +
                       "); fix whichever is wrong");
    out.push_back(f);
  }
  return out;
}

std::vector<glm::mat4> moverTrackFrames(const RawTrack& track, const spec::CaseSpec& spec,
                                        size_t mover) {
  std::vector<glm::mat4> out;
  for (const TrackSample& s :
       resampleTrack(track, offsetSeconds(spec.movers[mover].track_time_offset_s), spec.script.fps,
                     spec.script.frames))
    out.push_back(sampleMatrix(s));
  return out;
}

Tracks loadTracks(const spec::CaseSpec& spec) {
  Tracks t;
  t.fps = spec.script.fps;
  t.frames = spec.script.frames;
  JsonCache json;
  std::string key = "camera.track";
  try {
    if (!spec.camera.track.empty()) {
      const RawTrack raw = cameraRaw(spec, json);
      checkTrack(raw);
      t.camera = cameraTrackFrames(raw, spec);
      t.cameraHasFov = raw.hasFov;
      t.cameraHasNear = raw.hasNear;
      t.cameraHasFar = raw.hasFar;
    }
    t.movers.resize(spec.movers.size());
    for (size_t i = 0; i < spec.movers.size(); ++i) {
      if (spec.movers[i].track.empty()) continue;
      key = "movers[" + std::to_string(i) + "].track";
      const RawTrack raw = moverRaw(spec, i, json);
      checkTrack(raw);
      t.movers[i] = moverTrackFrames(raw, spec, i);
    }
  } catch (const TrackError& e) {
    // The case and its key first: the fix may be in either file.
    throw TrackError(spec.file.string() + ": " + key + ": " + e.what());
  }
  return t;
}

}  // namespace taa::script
