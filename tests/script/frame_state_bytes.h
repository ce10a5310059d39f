// A FrameState as the bytes of its fields, for "the same state" comparisons (frame order,
// track replays). Field by field, so struct padding never enters the comparison; every field
// of FrameState and CameraState is listed, so one the renderer reads cannot differ unseen.
#pragma once

#include <vector>

#include "script/frame_state.h"

namespace taa::test {

template <class T>
void appendBytes(std::vector<unsigned char>& out, const T& v) {
  const auto* p = reinterpret_cast<const unsigned char*>(&v);
  out.insert(out.end(), p, p + sizeof(T));
}

inline std::vector<unsigned char> cameraBytes(const script::CameraState& c) {
  std::vector<unsigned char> out;
  appendBytes(out, c.position);
  appendBytes(out, c.view);
  appendBytes(out, c.projection);
  appendBytes(out, c.viewProjection);
  appendBytes(out, c.fovY);
  appendBytes(out, c.aspect);
  appendBytes(out, c.nearPlane);
  appendBytes(out, c.farPlane);
  return out;
}

inline std::vector<unsigned char> frameStateBytes(const script::FrameState& fs) {
  std::vector<unsigned char> out;
  const auto camera = [&out](const script::CameraState& c) {
    const auto b = cameraBytes(c);
    out.insert(out.end(), b.begin(), b.end());
  };
  appendBytes(out, fs.frame);
  appendBytes(out, fs.time);
  appendBytes(out, fs.renderSize);
  appendBytes(out, fs.renderScale);
  camera(fs.camera);
  camera(fs.prevCamera);
  appendBytes(out, fs.jitter);
  appendBytes(out, fs.jitteredProjection);
  for (const auto& m : fs.movers) appendBytes(out, m);
  for (const auto& m : fs.prevMovers) appendBytes(out, m);
  for (double t : fs.moverAnimTime) appendBytes(out, t);
  for (double t : fs.prevMoverAnimTime) appendBytes(out, t);
  appendBytes(out, fs.worldAnimTime);
  appendBytes(out, fs.prevWorldAnimTime);
  appendBytes(out, fs.cameraCut);
  appendBytes(out, fs.resetHistory);
  return out;
}

}  // namespace taa::test
