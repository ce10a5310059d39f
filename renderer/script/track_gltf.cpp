#include "script/track_gltf.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "scene/scene_error.h"

namespace taa::script {

namespace {

// The node the track follows, with an error listing the candidates otherwise.
int findCameraNode(const scene::Model& model, const std::string& source, const std::string& name) {
  std::string cameras;
  std::vector<int> found;
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    const scene::Node& n = model.nodes[i];
    if (n.camera >= 0) cameras += (cameras.empty() ? "'" : ", '") + n.name + "'";
    if (name.empty() ? n.camera >= 0 : n.name == name) found.push_back(int(i));
  }
  if (cameras.empty()) cameras = "none";
  const std::string listed = "; camera nodes in the file: " + cameras;
  if (found.empty() && name.empty())
    throw TrackError(source + ": no node carries a camera; add a perspective camera to a node");
  if (found.empty())
    throw TrackError(source + ": no node is named '" + name + "'" + listed +
                     "; set camera.track_camera to one of them");
  if (found.size() > 1)
    throw TrackError(source + ": " +
                     (name.empty() ? std::string("several nodes carry a camera")
                                   : "several nodes are named '" + name + "'") +
                     listed + "; set camera.track_camera to a unique node name");
  if (model.nodes[size_t(found[0])].camera < 0)
    throw TrackError(source + ": node '" + name + "' has no camera" + listed);
  return found[0];
}

}  // namespace

RawTrack gltfCameraTrack(const std::filesystem::path& file, const std::string& cameraNode,
                         const std::vector<double>& times) {
  const std::string source = file.string();
  scene::Scene unused;  // meshes and textures are loaded too, and dropped
  scene::Model model;
  try {
    model = scene::loadGltf(file, unused);
  } catch (const scene::SceneError& e) {
    throw TrackError(e.what());
  }
  const int index = findCameraNode(model, source, cameraNode);
  const scene::Node& node = model.nodes[size_t(index)];
  const scene::Camera& camera = model.cameras[size_t(node.camera)];
  if (!camera.perspective)
    throw TrackError(source + ": node '" + node.name +
                     "' has an orthographic camera; the "
                     "harness renders perspective views only, export a perspective one");
  if (model.animations.empty())
    throw TrackError(source +
                     ": the file has no animation, so its camera does not move; "
                     "animate the camera node (the first animation is replayed)");
  const double duration = model.animations.front().duration;
  model.playing = {0};  // a camera track replays the first animation alone (docs/tracks.md)

  RawTrack track;
  track.source = source + ": node '" + node.name + "'";
  track.hasFov = track.hasNear = true;
  track.hasFar = camera.zfar > 0.0f;
  for (size_t n = 0; n < times.size(); ++n) {
    const double t = times[n];
    if (t < 0.0 || t > duration)
      throw TrackError(track.source + ": frame " + std::to_string(n) +
                       " replays t = " + trackNumber(t) + " s, outside the animation's 0 .. " +
                       trackNumber(duration) +
                       " s; the track is shorter than the case: lower script.frames, change "
                       "camera.track_time_offset_s or lengthen the animation");
    const glm::dmat4 world(scene::nodeWorldTransforms(model, t)[size_t(index)]);
    TrackSample s;
    s.time = t;
    s.where = track.source + " at t = " + trackNumber(t) + " s (frame " + std::to_string(n) + ")";
    s.position = glm::dvec3(world[3]);
    glm::dmat3 basis(world);
    for (int c = 0; c < 3; ++c) {
      const double len = glm::length(basis[c]);
      if (!(len > 0.0))
        throw TrackError(s.where +
                         ": the camera node's scale collapses an axis; remove the "
                         "zero scale");
      basis[c] /= len;  // a scaled camera still looks the same way
    }
    s.orientation = quatFromOrientation(basis);
    s.fovYDeg = static_cast<float>(glm::degrees(double(camera.yfov)));
    s.nearPlane = camera.znear;
    s.farPlane = camera.zfar;
    track.samples.push_back(std::move(s));
  }
  return track;
}

}  // namespace taa::script
