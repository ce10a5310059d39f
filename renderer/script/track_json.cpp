#include "script/track_json.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>

#include "core/json_guard.h"

namespace taa::script {

namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;  // written keys keep a readable order

std::string at(const std::string& file, const std::string& path) {
  return file + ": " + path;
}

// Reads one subject's frames, naming every problem by its key path.
class FrameReader {
 public:
  FrameReader(const std::string& file, double fps, TrackSubject subject)
      : file_(file), fps_(fps), subject_(subject) {}

  RawTrack read(const Json& node, const std::string& path) {
    RawTrack track;
    track.source = at(file_, path);
    if (!node.is_object()) fail(path, "expected an object {\"frames\": [...]}");
    keys(node, path, {"frames"});
    const auto frames = node.find("frames");
    if (frames == node.end() || !frames->is_array())
      fail(path, "expected \"frames\": [...], one object per recorded frame");
    for (size_t i = 0; i < frames->size(); ++i) {
      const std::string p = path + ".frames[" + std::to_string(i) + "]";
      track.samples.push_back(sample((*frames)[i], p, i));
      const Json& f = (*frames)[i];
      for (auto [key, flag] :
           {std::pair{"fov_y_deg", &track.hasFov}, std::pair{"near", &track.hasNear},
            std::pair{"far", &track.hasFar}}) {
        if (i == 0) *flag = f.contains(key);
        if (f.contains(key) != *flag)
          fail(p, std::string(*flag ? "has no " : "has ") + key + " but frames[0] " +
                      (*flag ? "does" : "does not") + "; give it in every frame or in none");
      }
    }
    return track;
  }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw TrackError(at(file_, path) + ": " + what);
  }

  void keys(const Json& node, const std::string& path, std::set<std::string> allowed) const {
    for (const auto& item : node.items())
      if (!allowed.count(item.key())) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(path + "." + item.key(), "unknown key; allowed here: " + list);
      }
  }

  double number(const Json& j, const std::string& path) const {
    if (!j.is_number()) fail(path, "expected a number");
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(path, "not a finite number; fix the exporter");
    return v;
  }

  float floatNumber(const Json& j, const std::string& path) const {
    const double v = number(j, path);
    if (std::fabs(v) > 3.0e38) fail(path, "beyond float range");
    return static_cast<float>(v);
  }

  std::vector<double> numbers(const Json& j, const std::string& path, size_t n) const {
    if (!j.is_array() || j.size() != n)
      fail(path, "expected an array of " + std::to_string(n) + " numbers");
    std::vector<double> out;
    for (size_t i = 0; i < n; ++i)
      out.push_back(number(j[i], path + "[" + std::to_string(i) + "]"));
    return out;
  }

  TrackSample sample(const Json& f, const std::string& path, size_t index) const {
    if (!f.is_object()) fail(path, "expected an object");
    if (subject_ == TrackSubject::Camera)
      keys(f, path, {"t", "position", "orientation", "basis", "fov_y_deg", "near", "far", "cut"});
    else
      keys(f, path, {"t", "position", "orientation", "scale", "matrix"});
    TrackSample s;
    s.where = at(file_, path);
    if (fps_ > 0.0) {
      if (f.contains("t"))
        fail(path + ".t",
             "the file sets a top-level fps, which times every frame; remove "
             "either fps or every \"t\"");
      s.time = static_cast<double>(index) / fps_;
    } else {
      if (!f.contains("t"))
        fail(path,
             "missing timestamp \"t\" (seconds); give every frame a \"t\", or set a "
             "top-level \"fps\" for frames recorded at a fixed rate");
      s.time = number(f["t"], path + ".t");
    }
    if (f.contains("matrix")) {
      if (f.contains("position") || f.contains("orientation") || f.contains("scale"))
        fail(path, "give either matrix or position/orientation/scale, not both");
      const auto m = numbers(f["matrix"], path + ".matrix", 16);
      glm::mat4 matrix;
      for (int i = 0; i < 16; ++i) {
        if (std::fabs(m[size_t(i)]) > 3.0e38) fail(path + ".matrix", "beyond float range");
        matrix[i / 4][i % 4] = static_cast<float>(m[size_t(i)]);
      }
      s.matrix = matrix;
      decomposeMatrix(matrix, s);
      return s;
    }
    if (!f.contains("position")) fail(path, "missing \"position\"");
    const auto p = numbers(f["position"], path + ".position", 3);
    s.position = {p[0], p[1], p[2]};
    if (f.contains("basis")) {
      const auto b = numbers(f["basis"], path + ".basis", 9);
      glm::dmat3 basis;
      for (int i = 0; i < 9; ++i) basis[i / 3][i % 3] = b[size_t(i)];
      s.basis = basis;
      s.orientation = quatFromOrientation(basis);
    } else if (!f.contains("orientation")) {
      fail(path, subject_ == TrackSubject::Mover
                     ? "missing \"orientation\" (x, y, z, w), or give a \"matrix\""
                     : "missing \"orientation\" (x, y, z, w)");
    }
    if (f.contains("orientation")) {
      const auto q = numbers(f["orientation"], path + ".orientation", 4);
      s.orientation = glm::dquat(q[3], q[0], q[1], q[2]);
    }
    if (f.contains("scale")) {
      const auto sc = numbers(f["scale"], path + ".scale", 3);
      s.scale = {sc[0], sc[1], sc[2]};
    }
    if (f.contains("fov_y_deg")) s.fovYDeg = floatNumber(f["fov_y_deg"], path + ".fov_y_deg");
    if (f.contains("near")) s.nearPlane = floatNumber(f["near"], path + ".near");
    if (f.contains("far")) s.farPlane = floatNumber(f["far"], path + ".far");
    if (f.contains("cut")) {
      if (!f["cut"].is_boolean()) fail(path + ".cut", "expected true or false");
      s.cut = f["cut"].get<bool>();
    }
    return s;
  }

  const std::string& file_;
  double fps_;
  TrackSubject subject_;
};

// The double that prints as the shortest decimal rounding back to `v`: nlohmann then
// prints that decimal, and reading it back as double and rounding gives `v` again.
double shortestFloat(float v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::strtod(std::string(buf, r.ptr).c_str(), nullptr);
}

OrderedJson frameJson(const RawTrack& track, const TrackSample& s, bool timed) {
  OrderedJson j = OrderedJson::object();
  if (timed) j["t"] = s.time;
  if (s.matrix) {
    OrderedJson m = OrderedJson::array();
    for (int i = 0; i < 16; ++i) m.push_back(shortestFloat((*s.matrix)[i / 4][i % 4]));
    j["matrix"] = m;
    return j;
  }
  j["position"] = {s.position.x, s.position.y, s.position.z};
  j["orientation"] = {s.orientation.x, s.orientation.y, s.orientation.z, s.orientation.w};
  if (s.basis) {
    OrderedJson b = OrderedJson::array();
    for (int i = 0; i < 9; ++i) b.push_back((*s.basis)[i / 3][i % 3]);
    j["basis"] = b;
  }
  if (s.scale != glm::dvec3(1.0)) j["scale"] = {s.scale.x, s.scale.y, s.scale.z};
  if (track.hasFov) j["fov_y_deg"] = shortestFloat(s.fovYDeg);
  if (track.hasNear) j["near"] = shortestFloat(s.nearPlane);
  if (track.hasFar) j["far"] = shortestFloat(s.farPlane);
  if (s.cut) j["cut"] = true;
  return j;
}

std::string framesText(const RawTrack& track, bool timed, const std::string& indent) {
  std::string out = "{\"frames\": [\n";
  for (size_t i = 0; i < track.samples.size(); ++i)
    out += indent + "  " + frameJson(track, track.samples[i], timed).dump() +
           (i + 1 < track.samples.size() ? ",\n" : "\n");
  return out + indent + "]}";
}

}  // namespace

TrackFile parseJsonTrack(const std::string& text, const std::string& file) {
  if (const std::string problem = jsonStructureProblem(text); !problem.empty())
    throw TrackError(file + ": " + problem);
  Json root;
  try {
    root = Json::parse(text);
  } catch (const Json::parse_error& e) {
    // nlohmann reports a byte offset; users need line:column.
    int line = 1, column = 1;
    for (size_t i = 0; i + 1 < std::min<size_t>(e.byte, text.size()); ++i) {
      column = text[i] == '\n' ? 1 : column + 1;
      line += text[i] == '\n';
    }
    throw TrackError(file + ":" + std::to_string(line) + ":" + std::to_string(column) +
                     ": not valid JSON (" + jsonErrorWithoutContent(e.what()) +
                     "); fix the syntax there (JSON has no NaN or Infinity: those are exporter "
                     "bugs)");
  } catch (const Json::exception& e) {  // e.g. a number overflowing double: 1e999
    throw TrackError(file + ": not valid JSON (" + jsonErrorWithoutContent(e.what()) +
                     "); JSON has no NaN or Infinity, those are exporter bugs");
  }
  if (!root.is_object()) throw TrackError(file + ": a track must be a JSON object {...}");
  const std::set<std::string> allowed = {"format", "version", "description",
                                         "fps",    "camera",  "movers"};
  for (const auto& item : root.items())
    if (!allowed.count(item.key()))
      throw TrackError(at(file, item.key()) +
                       ": unknown key; allowed: camera, description, "
                       "format, fps, movers, version");
  if (root.value("format", Json()) != "taa-track" || root.value("version", Json()) != 1)
    throw TrackError(file +
                     ": not a track file; it must start with \"format\": \"taa-track\", "
                     "\"version\": 1 (docs/tracks.md)");
  TrackFile out;
  if (root.contains("description") && root["description"].is_string())
    out.description = root["description"].get<std::string>();
  if (root.contains("fps")) {
    const Json& f = root["fps"];
    if (!f.is_number() || !(f.get<double>() > 0.0) || !std::isfinite(f.get<double>()))
      throw TrackError(at(file, "fps") + ": expected a positive frame rate");
    out.fps = f.get<double>();
  }
  if (root.contains("camera"))
    out.camera = FrameReader(file, out.fps, TrackSubject::Camera).read(root["camera"], "camera");
  if (root.contains("movers")) {
    const Json& m = root["movers"];
    if (!m.is_array()) throw TrackError(at(file, "movers") + ": expected an array [...]");
    for (size_t i = 0; i < m.size(); ++i)
      out.movers.push_back(FrameReader(file, out.fps, TrackSubject::Mover)
                               .read(m[i], "movers[" + std::to_string(i) + "]"));
  }
  return out;
}

std::string writeJsonTrack(const TrackFile& track) {
  const bool timed = !(track.fps > 0.0);
  std::vector<std::string> entries = {"\"format\": \"taa-track\"", "\"version\": 1"};
  if (!track.description.empty())
    entries.push_back("\"description\": " + Json(track.description).dump());
  if (!timed) {
    const bool whole = track.fps == std::floor(track.fps) && track.fps < 1e9;
    entries.push_back("\"fps\": " +
                      (whole ? Json(static_cast<long long>(track.fps)) : Json(track.fps)).dump());
  }
  if (track.camera) entries.push_back("\"camera\": " + framesText(*track.camera, timed, "  "));
  if (!track.movers.empty()) {
    std::string movers = "\"movers\": [\n";
    for (size_t i = 0; i < track.movers.size(); ++i)
      movers += "    " + framesText(track.movers[i], timed, "    ") +
                (i + 1 < track.movers.size() ? ",\n" : "\n");
    entries.push_back(movers + "  ]");
  }
  std::string out = "{\n";
  for (size_t i = 0; i < entries.size(); ++i)
    out += "  " + entries[i] + (i + 1 < entries.size() ? ",\n" : "\n");
  return out + "}\n";
}

}  // namespace taa::script
