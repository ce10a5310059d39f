// An animated glTF camera as a track: the camera node's world transform under the
// file's first animation (the node looks down its local -Z with +Y up, as glTF
// specifies, which is the harness's camera convention too) and its perspective lens.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "script/track.h"

namespace taa::script {

// Samples the camera at each of `times` (seconds into the animation), so resampling
// hits every sample exactly and blends nothing a second time. `cameraNode` names the
// node; empty picks the only node with a camera. The lens becomes fov_y_deg (yfov),
// near (znear) and far (zfar, when given). Throws TrackError (a time outside the
// animation, no such node, an orthographic camera, an unreadable file).
RawTrack gltfCameraTrack(const std::filesystem::path& file, const std::string& cameraNode,
                         const std::vector<double>& times);

}  // namespace taa::script
