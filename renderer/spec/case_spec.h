// A whole case, every default filled in. Parsed from JSON by harness/case/,
// consumed by the renderer; nothing else configures a run.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "spec/fields.h"
#include "spec/inject_spec.h"
#include "spec/render_spec.h"
#include "spec/scene_spec.h"
#include "spec/script_spec.h"
#include "spec/taa_spec.h"

namespace taa::script {
struct Tracks;
}

namespace taa::spec {

struct CaseSpec {
  std::string name;             // the case file's stem
  std::filesystem::path file;   // where it was read from; relative paths resolve against its folder
  std::string description;
  SceneSpec scene;
  LightingSpec lighting;
  MaterialSpec material;
  RenderSpec render;
  TimingSpec script;
  CameraSpec camera;
  std::vector<MoverSpec> movers;
  JitterSpec jitter;
  TaaSpec taa;
  AdaptiveSpec adaptive;
  TscmaaSpec tscmaa;
  PostSpec post;
  DebugSpec debug;
  OutputSpec output;
  ReferenceSpec reference;
  InjectSpec inject;
  // The recorded tracks (camera.track, movers[].track) read and resampled to the
  // case's frames once, when the case is loaded (script::loadTracks); frame
  // evaluation only indexes them. Null when the case sets no track.
  std::shared_ptr<const script::Tracks> tracks;
};

template <class V>
void fields(V& v, CaseSpec& s) {
  v.field("description", s.description, Meta{"what the case shows and why it exists", ""});
  v.object("scene", s.scene, Meta{"scene source", ""});
  v.object("lighting", s.lighting, Meta{"directional + ambient Blinn-Phong light", ""});
  v.object("material", s.material, Meta{"material overrides", ""});
  v.object("render", s.render, Meta{"resolution and render path", ""});
  v.object("script", s.script, Meta{"fixed-timestep replay", ""});
  v.object("camera", s.camera, Meta{"camera pose, path and procedural motion", ""});
  v.list("movers", s.movers, Meta{"moving objects", ""});
  v.object("jitter", s.jitter, Meta{"projection jitter sequence", ""});
  v.object("taa", s.taa, Meta{"temporal resolve", ""});
  v.object("adaptive", s.adaptive, Meta{"adaptive ray tracing (taa.mode adaptive)", ""});
  v.object("tscmaa", s.tscmaa, Meta{"TSCMAA settings (taa.mode tscmaa)", ""});
  v.object("post", s.post, Meta{"passes around the resolve", ""});
  v.object("debug", s.debug, Meta{"debug views", ""});
  v.object("output", s.output, Meta{"frames and buffers written", ""});
  v.object("reference", s.reference, Meta{"supersampled ground truth", ""});
  v.object("inject", s.inject,
           Meta{"stress: non-finite values written into the rendered colour", ""});
}

}  // namespace taa::spec
