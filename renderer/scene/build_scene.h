// The whole scene of a case: the world plus one model per mover.
#pragma once

#include "scene/scene.h"
#include "spec/case_spec.h"

namespace taa::scene {

// models[0] is the world (spec.scene.gltf resolved against the case file's folder,
// else the built-in scene), then one model per spec.movers entry in order: a cube or
// sphere in the mover's colour, or its glTF. spec.material.alpha_mode then overrides
// every material with alpha (see applyAlphaOverride). Throws SceneError.
Scene buildScene(const spec::CaseSpec& spec);

// Whether a material is see-through anywhere: a non-opaque mode, a base-colour alpha
// below 1 or a texture with alpha below 255.
bool materialHasAlpha(const Scene& scene, const Material& m);

// Forces every material with alpha to alpha testing (with `cutoff`) or blending;
// spec::AlphaMode::Asset leaves materials as they are.
void applyAlphaOverride(Scene& scene, spec::AlphaMode mode, float cutoff);

}  // namespace taa::scene
