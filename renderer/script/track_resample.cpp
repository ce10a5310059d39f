#include "script/track_resample.h"

#include <algorithm>
#include <glm/gtc/quaternion.hpp>

#include "script/timing.h"

namespace taa::script {

namespace {

double frameTimeAt(double offsetS, int fps, int frame) {
  spec::TimingSpec timing;
  timing.fps = fps;
  return offsetS + frameTime(timing, frame);
}

}  // namespace

TrackSample interpolateSamples(const TrackSample& a, const TrackSample& b, double s) {
  TrackSample out;
  out.time = a.time + (b.time - a.time) * s;
  out.where = a.where + " .. " + b.where;
  out.position = a.position + (b.position - a.position) * s;
  out.scale = a.scale + (b.scale - a.scale) * s;
  // The shorter arc: q and -q are the same orientation. GLM's slerp (0.9.9) also negates one
  // when their dot is negative; doing it here keeps the arc ours whatever GLM does.
  const glm::dquat qa = glm::normalize(a.orientation);
  glm::dquat qb = glm::normalize(b.orientation);
  if (glm::dot(qa, qb) < 0.0) qb = -qb;
  out.orientation = glm::normalize(glm::slerp(qa, qb, s));
  auto lerp = [s](float x, float y) {
    return static_cast<float>(double(x) + (double(y) - double(x)) * s);
  };
  out.fovYDeg = lerp(a.fovYDeg, b.fovYDeg);
  out.nearPlane = lerp(a.nearPlane, b.nearPlane);
  out.farPlane = lerp(a.farPlane, b.farPlane);
  return out;
}

std::vector<TrackSample> resampleTrack(const RawTrack& track, double offsetS, int fps, int frames) {
  const auto& in = track.samples;
  std::vector<TrackSample> out;
  out.reserve(size_t(std::max(frames, 0)));
  const double first = in.front().time, last = in.back().time;
  auto byTime = [](double t, const TrackSample& x) { return t < x.time; };
  for (int n = 0; n < frames; ++n) {
    const double t = frameTimeAt(offsetS, fps, n);
    if (t < first || t > last)
      throw TrackError(track.source + ": frame " + std::to_string(n) + " replays t = " +
                       trackNumber(t) + " s (track_time_offset_s + frame / " + std::to_string(fps) +
                       "), outside the track's " + trackNumber(first) + " .. " + trackNumber(last) +
                       " s; the track is shorter than the case: record a longer track, lower "
                       "script.frames or change track_time_offset_s");
    // k: the last sample at or before t.
    const size_t k = size_t(std::upper_bound(in.begin(), in.end(), t, byTime) - in.begin()) - 1;
    if (in[k].time == t || in[k + 1].cut) {
      out.push_back(in[k]);
    } else {
      out.push_back(
          interpolateSamples(in[k], in[k + 1], (t - in[k].time) / (in[k + 1].time - in[k].time)));
    }
    // A teleport recorded since the previous frame makes this frame a cut.
    const double prev = frameTimeAt(offsetS, fps, n - 1);
    out.back().cut = false;
    for (size_t j = k + 1; j-- > 0 && in[j].time > prev;)
      if (in[j].cut) out.back().cut = true;
  }
  return out;
}

}  // namespace taa::script
