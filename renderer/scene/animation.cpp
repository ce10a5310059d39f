// Node animation sampling (glTF 2.0 semantics) and hierarchy evaluation.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <set>
#include <string>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/scene.h"

namespace taa::scene {
namespace {

glm::quat toQuat(const glm::vec4& v) {
  return glm::quat(v.w, v.x, v.y, v.z);
}

// Spherical interpolation along the shorter arc, as the glTF spec's reference does;
// glm::slerp would not flip the sign and could take the long way round.
glm::quat slerpShortest(glm::quat a, glm::quat b, float t) {
  if (glm::dot(a, b) < 0.0f) b = -b;
  return glm::normalize(glm::slerp(a, b, t));
}

// Samples one channel at `t` (seconds within the animation). Before the first key and
// after the last the end values hold, as the spec requires.
glm::vec4 sample(const AnimChannel& ch, float t, bool rotation) {
  const size_t n = ch.times.size();
  const bool cubic = ch.interpolation == Interpolation::CubicSpline;
  auto value = [&](size_t k) { return cubic ? ch.values[3 * k + 1] : ch.values[k]; };
  assert(n > 0 && ch.values.size() == (cubic ? 3 * n : n));
  if (t <= ch.times.front() || n == 1) return value(0);
  if (t >= ch.times.back()) return value(n - 1);
  // The key k with times[k] <= t < times[k + 1].
  const size_t k =
      size_t(std::upper_bound(ch.times.begin(), ch.times.end(), t) - ch.times.begin()) - 1;
  const float t0 = ch.times[k], td = ch.times[k + 1] - t0;
  const float s = td > 0.0f ? (t - t0) / td : 0.0f;
  switch (ch.interpolation) {
    case Interpolation::Step:
      return value(k);
    case Interpolation::Linear:
      if (rotation) {
        const glm::quat q = slerpShortest(toQuat(value(k)), toQuat(value(k + 1)), s);
        return {q.x, q.y, q.z, q.w};
      }
      return value(k) + (value(k + 1) - value(k)) * s;
    case Interpolation::CubicSpline: {
      // Hermite spline with tangents scaled by the key interval (glTF spec, Appendix C).
      const glm::vec4 p0 = ch.values[3 * k + 1], m0 = ch.values[3 * k + 2] * td;
      const glm::vec4 p1 = ch.values[3 * (k + 1) + 1], m1 = ch.values[3 * (k + 1)] * td;
      const float s2 = s * s, s3 = s2 * s;
      glm::vec4 v = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 +
                    (s3 - s2) * m1;
      if (rotation) v = glm::normalize(v);
      return v;
    }
  }
  return value(k);
}

// Morph weights of a Weights channel at `t`, the same key rules as sample().
std::vector<float> sampleWeights(const AnimChannel& ch, float t) {
  const size_t n = ch.times.size(), w = size_t(ch.targets);
  const bool cubic = ch.interpolation == Interpolation::CubicSpline;
  auto value = [&](size_t k, size_t part) {  // part: 0 in-tangent, 1 value, 2 out-tangent
    return &ch.weights[((cubic ? 3 * k + part : k)) * w];
  };
  std::vector<float> out(w);
  if (t <= ch.times.front() || n == 1 || t >= ch.times.back()) {
    const float* v = value(t >= ch.times.back() ? n - 1 : 0, 1);
    out.assign(v, v + w);
    return out;
  }
  const size_t k =
      size_t(std::upper_bound(ch.times.begin(), ch.times.end(), t) - ch.times.begin()) - 1;
  const float t0 = ch.times[k], td = ch.times[k + 1] - t0;
  const float s = td > 0.0f ? (t - t0) / td : 0.0f;
  const float s2 = s * s, s3 = s2 * s;
  for (size_t i = 0; i < w; ++i) {
    switch (ch.interpolation) {
      case Interpolation::Step:
        out[i] = value(k, 1)[i];
        break;
      case Interpolation::Linear:
        out[i] = value(k, 1)[i] + (value(k + 1, 1)[i] - value(k, 1)[i]) * s;
        break;
      case Interpolation::CubicSpline:
        out[i] = (2 * s3 - 3 * s2 + 1) * value(k, 1)[i] + (s3 - 2 * s2 + s) * value(k, 2)[i] * td +
                 (-2 * s3 + 3 * s2) * value(k + 1, 1)[i] + (s3 - s2) * value(k + 1, 0)[i] * td;
        break;
    }
  }
  return out;
}

// Node-local TRS after the playing animations are sampled; `loop` wraps each
// animation's time into its own duration.
std::vector<Node> animatedNodes(const Model& m, double time, bool loop) {
  std::vector<Node> nodes = m.nodes;
  for (const int a : playingAnimations(m)) {
    if (a < 0 || size_t(a) >= m.animations.size()) continue;
    const Animation& anim = m.animations[size_t(a)];
    double t = time;
    if (loop && anim.duration > 0.0f) {
      t = std::fmod(time, double(anim.duration));
      if (t < 0.0) t += double(anim.duration);
    }
    for (const AnimChannel& ch : anim.channels) {
      if (ch.node < 0 || size_t(ch.node) >= nodes.size() || ch.times.empty()) continue;
      Node& n = nodes[size_t(ch.node)];
      if (ch.path == AnimPath::Weights) {
        n.weights = sampleWeights(ch, float(t));
        continue;
      }
      const glm::vec4 v = sample(ch, float(t), ch.path == AnimPath::Rotation);
      switch (ch.path) {
        case AnimPath::Translation:
          n.translation = glm::vec3(v);
          break;
        case AnimPath::Rotation:
          n.rotation = toQuat(v);
          break;
        case AnimPath::Scale:
          n.scale = glm::vec3(v);
          break;
        case AnimPath::Weights:
          break;
      }
    }
  }
  return nodes;
}

std::vector<glm::mat4> worldTransforms(const std::vector<Node>& nodes) {
  std::vector<glm::mat4> world(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    const Node& n = nodes[i];
    const glm::mat4 local = glm::translate(glm::mat4(1.0f), n.translation) *
                            glm::mat4_cast(n.rotation) * glm::scale(glm::mat4(1.0f), n.scale);
    assert(n.parent < int(i));
    world[i] = n.parent >= 0 ? world[size_t(n.parent)] * local : local;
  }
  return world;
}

}  // namespace

std::vector<int> defaultAnimations(const Model& m) {
  std::set<std::pair<int, AnimPath>> driven;
  std::vector<int> out;
  for (size_t a = 0; a < m.animations.size(); ++a) {
    const auto& channels = m.animations[a].channels;
    const bool clash = std::any_of(channels.begin(), channels.end(), [&](const AnimChannel& c) {
      return driven.count({c.node, c.path}) > 0;
    });
    if (clash) continue;
    for (const AnimChannel& c : channels) driven.insert({c.node, c.path});
    out.push_back(int(a));
  }
  return out;
}

std::vector<int> playingAnimations(const Model& m) {
  return m.playing.empty() ? defaultAnimations(m) : m.playing;
}

std::string describeAnimations(const Model& m) {
  if (m.animations.empty()) return "";
  const std::vector<int> playing = playingAnimations(m);
  auto name = [&](int a) {
    return std::to_string(a) + " '" + m.animations[size_t(a)].name + "'";
  };
  std::string plays, left;
  for (const int a : playing) plays += (plays.empty() ? "" : ", ") + name(a);
  for (int a = 0; a < int(m.animations.size()); ++a)
    if (std::find(playing.begin(), playing.end(), a) == playing.end())
      left += (left.empty() ? "" : ", ") + name(a);
  std::string line = m.name + " plays " + (plays.empty() ? "no animation" : plays);
  if (!left.empty())
    line += m.playing.empty()
                ? "; not " + left + ", which drive what an earlier one drives (pick with "
                                    "scene.animations or movers[].animations)"
                : "; not " + left + " (not picked by the case)";
  return line;
}

std::vector<glm::mat4> nodeWorldTransforms(const Model& m, double time) {
  return worldTransforms(animatedNodes(m, time, false));
}

bool modelAnimates(const Model& m) {
  for (const int a : playingAnimations(m))
    if (a >= 0 && size_t(a) < m.animations.size() && m.animations[size_t(a)].duration > 0.0f)
      return true;
  return false;
}

std::vector<MeshDraw> poseModel(const Scene& scene, int model, double time) {
  const Model& m = scene.models[size_t(model)];
  const std::vector<Node> nodes = animatedNodes(m, time, true);
  const std::vector<glm::mat4> world = worldTransforms(nodes);
  std::vector<MeshDraw> draws;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const Node& n = nodes[i];
    if (n.mesh < 0) continue;
    MeshDraw d{int(i), n.mesh, world[i], {}, {}};
    const Mesh& mesh = scene.meshes[size_t(n.mesh)];
    if (!mesh.targets.empty()) {
      d.weights = n.weights.empty() ? mesh.weights : n.weights;
      d.weights.resize(mesh.targets.size(), 0.0f);
    }
    if (n.skin >= 0 && size_t(n.skin) < m.skins.size() && !mesh.skin.empty()) {
      const Skin& skin = m.skins[size_t(n.skin)];
      for (size_t j = 0; j < skin.joints.size(); ++j)
        d.joints.push_back(world[size_t(skin.joints[j])] * skin.inverseBind[j]);
      d.transform = glm::mat4(1.0f);
    }
    for (const glm::mat4& instance : n.instances) {
      MeshDraw copy = d;
      copy.transform = world[i] * instance;
      draws.push_back(std::move(copy));
    }
    if (n.instances.empty()) draws.push_back(std::move(d));
  }
  return draws;
}

void modelBounds(const Scene& scene, int model, const std::vector<double>& times, glm::vec3& lo,
                 glm::vec3& hi) {
  bool any = false;
  lo = hi = glm::vec3(0.0f);
  auto add = [&](const glm::vec3& p) {
    lo = any ? glm::min(lo, p) : p;
    hi = any ? glm::max(hi, p) : p;
    any = true;
  };
  for (const double t : times)
    for (const MeshDraw& d : poseModel(scene, model, t)) {
      const Mesh& mesh = scene.meshes[size_t(d.mesh)];
      if (d.deformed()) {  // the joints and weights move vertices beyond the rest bounds
        for (const Vertex& v : deformVertices(scene, d))
          add(glm::vec3(d.transform * glm::vec4(v.position, 1.0f)));
        continue;
      }
      for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? mesh.boundsMax.x : mesh.boundsMin.x,
                               (c & 2) ? mesh.boundsMax.y : mesh.boundsMin.y,
                               (c & 4) ? mesh.boundsMax.z : mesh.boundsMin.z);
        add(glm::vec3(d.transform * glm::vec4(corner, 1.0f)));
      }
    }
}

void modelBounds(const Scene& scene, int model, glm::vec3& lo, glm::vec3& hi) {
  modelBounds(scene, model, {0.0}, lo, hi);
}

}  // namespace taa::scene
