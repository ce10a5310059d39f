#include "script/track_csv.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <vector>

namespace taa::script {

namespace {

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> splitCells(const std::string& line) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string::npos ? comma : comma - start)));
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// Columns a subject accepts, in the order docs/tracks.md lists them.
std::vector<std::string> allowedColumns(TrackSubject subject) {
  std::vector<std::string> cols = {"time", "frame", "px", "py", "pz", "qx", "qy", "qz", "qw"};
  if (subject == TrackSubject::Camera)
    cols.insert(cols.end(), {"fov_y_deg", "near", "far", "cut"});
  else
    cols.insert(cols.end(), {"sx", "sy", "sz"});
  return cols;
}

class CsvReader {
 public:
  CsvReader(const std::string& file, TrackSubject subject) : file_(file), subject_(subject) {
    track_.source = file;
  }

  RawTrack run(const std::string& text);

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw TrackError(file_ + ":" + std::to_string(line) + ": " + what);
  }
  void directive(int line, const std::string& comment);
  void header(int line, const std::string& text);
  void row(int line, const std::string& text);
  double value(int line, const std::vector<std::string>& cells, const std::string& column) const;
  bool has(const std::string& column) const { return columns_.count(column) > 0; }

  const std::string& file_;
  TrackSubject subject_;
  RawTrack track_;
  std::map<std::string, size_t> columns_;
  std::vector<std::string> names_;
  double fps_ = 0.0;
  int fpsLine_ = 0;
  long long lastFrame_ = 0;
  int lastLine_ = 0;
};

RawTrack CsvReader::run(const std::string& text) {
  // A spreadsheet's "CSV UTF-8" starts with a byte-order mark, which would join the first
  // column's name; it holds no line, so dropping it keeps every line number.
  size_t start = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  for (int line = 1; start <= text.size(); ++line) {
    const size_t end = std::min(text.find('\n', start), text.size());
    const std::string content = trim(text.substr(start, end - start));
    start = end + 1;
    if (content.empty()) continue;
    if (content[0] == '#') {
      directive(line, content);
    } else if (names_.empty()) {
      header(line, content);
    } else {
      row(line, content);
    }
  }
  if (names_.empty())
    throw TrackError(file_ + ": no header line; start the file with the column names, e.g. " +
                     (subject_ == TrackSubject::Camera ? "time,px,py,pz,qx,qy,qz,qw,fov_y_deg"
                                                       : "time,px,py,pz,qx,qy,qz,qw"));
  if (fps_ > 0.0 && !has("frame"))
    fail(fpsLine_, "'# fps' applies only to a frame column; remove it or number the rows by frame");
  return std::move(track_);
}

void CsvReader::directive(int line, const std::string& comment) {
  const std::string body = trim(comment.substr(1));
  if (body.rfind("fps:", 0) != 0) return;  // an ordinary comment
  const std::string v = trim(body.substr(4));
  double fps = 0.0;
  const auto r = std::from_chars(v.data(), v.data() + v.size(), fps);
  if (r.ec != std::errc() || r.ptr != v.data() + v.size() || !(fps > 0.0) || !std::isfinite(fps))
    fail(line, "'# fps: " + v + "' is not a positive frame rate");
  if (!names_.empty()) fail(line, "'# fps' must come before the header line");
  fps_ = fps;
  fpsLine_ = line;
}

void CsvReader::header(int line, const std::string& text) {
  const std::vector<std::string> allowed = allowedColumns(subject_);
  names_ = splitCells(text);
  for (size_t i = 0; i < names_.size(); ++i) {
    const std::string& n = names_[i];
    if (std::find(allowed.begin(), allowed.end(), n) == allowed.end())
      fail(line, "unknown column '" + n + "'; a " +
                     (subject_ == TrackSubject::Camera ? "camera" : "mover") + " track allows " +
                     joined(allowed));
    if (!columns_.emplace(n, i).second) fail(line, "column '" + n + "' appears twice");
  }
  if (has("time") == has("frame"))
    fail(line, "give exactly one of the columns time (seconds) or frame (with '# fps: N')");
  for (const char* c : {"px", "py", "pz", "qx", "qy", "qz", "qw"})
    if (!has(c))
      fail(line, std::string("missing column '") + c +
                     "'; every track needs px, py, "
                     "pz (position) and qx, qy, qz, qw (unit orientation quaternion)");
  const int scales = int(has("sx")) + int(has("sy")) + int(has("sz"));
  if (scales != 0 && scales != 3) fail(line, "give all of sx, sy, sz or none");
  if (has("frame") && fps_ <= 0.0)
    fail(line, "a frame column needs the capture rate: add a line '# fps: 60' above the header");
  track_.hasFov = has("fov_y_deg");
  track_.hasNear = has("near");
  track_.hasFar = has("far");
}

double CsvReader::value(int line, const std::vector<std::string>& cells,
                        const std::string& column) const {
  const std::string& cell = cells[columns_.at(column)];
  if (cell.empty()) {
    if (column == "time" || column == "frame")
      fail(line, "missing timestamp (column " + column + " is empty); every sample needs one");
    fail(line, "column " + column + " is empty; give a number");
  }
  const char* first = cell.data() + (cell[0] == '+' ? 1 : 0);
  double v = 0.0;
  const auto r = std::from_chars(first, cell.data() + cell.size(), v);
  if (r.ec == std::errc::result_out_of_range || (r.ec == std::errc() && !std::isfinite(v)))
    fail(line, "column " + column + ": '" + cell + "' is not a finite number; fix the exporter");
  if (r.ec != std::errc() || r.ptr != cell.data() + cell.size())
    fail(line, "column " + column + ": '" + cell + "' is not a number");
  return v;
}

void CsvReader::row(int line, const std::string& text) {
  const std::vector<std::string> cells = splitCells(text);
  if (cells.size() != names_.size())
    fail(line, std::to_string(cells.size()) + " values for " + std::to_string(names_.size()) +
                   " columns (" + joined(names_) + ")");
  TrackSample s;
  s.where = file_ + ":" + std::to_string(line);
  auto get = [&](const char* c) { return value(line, cells, c); };
  if (has("time")) {
    s.time = get("time");
  } else {
    const double f = get("frame");
    if (f != std::floor(f) || std::fabs(f) > 1e9) fail(line, "frame must be a whole number");
    const auto frame = static_cast<long long>(f);
    if (!track_.samples.empty()) {
      const std::string prev =
          " (line " + std::to_string(lastLine_) + " has frame " + std::to_string(lastFrame_) + ")";
      if (frame == lastFrame_) fail(line, "frame " + std::to_string(frame) + " repeats" + prev);
      if (frame < lastFrame_) fail(line, "frame numbers must increase" + prev);
      if (frame > lastFrame_ + 1)
        fail(line, "frames " + std::to_string(lastFrame_ + 1) + " to " + std::to_string(frame - 1) +
                       " are missing" + prev + "; export every frame or use a time column");
    }
    lastFrame_ = frame;
    s.time = static_cast<double>(frame) / fps_;
  }
  lastLine_ = line;
  s.position = {get("px"), get("py"), get("pz")};
  s.orientation = glm::dquat(get("qw"), get("qx"), get("qy"), get("qz"));
  if (has("sx")) s.scale = {get("sx"), get("sy"), get("sz")};
  auto asFloat = [&](const char* c) {
    const double v = get(c);
    if (std::fabs(v) > 3.0e38) fail(line, std::string("column ") + c + " is beyond float range");
    return static_cast<float>(v);
  };
  if (track_.hasFov) s.fovYDeg = asFloat("fov_y_deg");
  if (track_.hasNear) s.nearPlane = asFloat("near");
  if (track_.hasFar) s.farPlane = asFloat("far");
  if (has("cut")) {
    const double c = get("cut");
    if (c != 0.0 && c != 1.0) fail(line, "cut must be 0 or 1");
    s.cut = c == 1.0;
  }
  track_.samples.push_back(std::move(s));
}

}  // namespace

RawTrack parseCsvTrack(const std::string& text, const std::string& file, TrackSubject subject) {
  return CsvReader(file, subject).run(text);
}

}  // namespace taa::script
