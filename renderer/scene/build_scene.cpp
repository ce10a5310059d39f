#include "scene/build_scene.h"

#include <algorithm>

#include "common/shared.h"
#include "core/image_io.h"
#include "core/input_file.h"
#include "scene/gltf_loader.h"
#include "scene/procedural.h"
#include "scene/scene_error.h"
#include "scene/textures.h"
#include "scene/trace_textures.h"
#include "spec/taa_modes.h"

namespace taa::scene {
namespace {

// Case paths are relative to the case file and must stay inside its folder tree. The
// case validator checks this too; repeating it here keeps buildScene safe for callers
// that skip validation. The glTF loader confines what the glTF itself refers to.
std::filesystem::path resolve(const spec::CaseSpec& spec, const std::string& key,
                              const std::string& path) {
  const std::filesystem::path p(path);
  bool escapes = path.find("://") != std::string::npos || p.is_absolute() || p.has_root_name();
  for (const auto& part : p.lexically_normal()) escapes = escapes || part == "..";
  if (escapes)
    throw SceneError(spec.file, key + ": '" + path +
                                    "' is not a relative path inside the case's folder; move the "
                                    "asset under the case's folder and give its relative path");
  // The lexical rule above gives the clearer message; this one also sees symbolic links.
  try {
    containedRealPath(spec.file.parent_path(), spec.file.parent_path() / p, key);
  } catch (const InputFileError& e) {
    throw SceneError(spec.file, e.what());
  }
  return spec.file.parent_path() / p;
}

// Resolves a case's animation picks (names, or decimal indices) into model.playing.
void selectAnimations(const spec::CaseSpec& spec, const std::string& key,
                      const std::vector<std::string>& picks, Model& model) {
  std::string available;
  for (size_t i = 0; i < model.animations.size(); ++i)
    available += (i ? ", " : "") + std::to_string(i) + " '" + model.animations[i].name + "'";
  for (size_t p = 0; p < picks.size(); ++p) {
    const std::string& pick = picks[p];
    int found = -1;
    for (size_t i = 0; i < model.animations.size() && found < 0; ++i)
      if (model.animations[i].name == pick) found = int(i);
    const bool digits = !pick.empty() && pick.size() < 9 &&
                        pick.find_first_not_of("0123456789") == std::string::npos;
    if (found < 0 && digits && size_t(std::stoi(pick)) < model.animations.size())
      found = std::stoi(pick);
    if (found < 0)
      throw SceneError(spec.file, key + "[" + std::to_string(p) + "]: '" + pick +
                                      "' is neither the name nor the index of an animation of " +
                                      model.name + " (it has " +
                                      (available.empty() ? "none" : available) +
                                      "); pick one of those or remove the entry");
    model.playing.push_back(found);
  }
}

}  // namespace

bool materialHasAlpha(const Scene& scene, const Material& m) {
  if (m.alphaMode != AlphaMode::Opaque || m.baseColorFactor.a < 1.0f) return true;
  return m.baseColorTexture >= 0 &&
         hasTranslucentTexels(scene.textures[size_t(m.baseColorTexture)]);
}

void applyAlphaOverride(Scene& scene, spec::AlphaMode mode, float cutoff) {
  if (mode == spec::AlphaMode::Asset) return;
  for (Material& m : scene.materials) {
    if (!materialHasAlpha(scene, m)) continue;
    if (mode == spec::AlphaMode::Mask) {
      m.alphaMode = AlphaMode::Mask;
      m.alphaCutoff = cutoff;
    } else {
      m.alphaMode = AlphaMode::Blend;
    }
  }
}

namespace {
// material.alpha_mode overrides materials with alpha only; a scene without any has nothing
// to test or blend.
void checkAlphaOverride(const spec::CaseSpec& spec, const Scene& scene) {
  if (spec.material.alpha_mode == spec::AlphaMode::Asset) return;
  if (std::none_of(scene.materials.begin(), scene.materials.end(),
                   [&](const Material& m) { return materialHasAlpha(scene, m); }))
    throw SceneError(spec.file,
                     "material.alpha_mode: no material of the scene has alpha (an alpha mode, a "
                     "base colour alpha below 1 or translucent texels), so it would change "
                     "nothing; remove the key or use such a scene (foliage, a glTF with alpha)");
}

// material.normal_strength acts only on normal-mapped materials, and only where the raster
// shades: the tracer has no normal maps, so its pixels would disagree with the raster's.
void checkNormalStrength(const spec::CaseSpec& spec, const Scene& scene) {
  const bool mapped = std::any_of(scene.materials.begin(), scene.materials.end(),
                                  [](const Material& m) { return m.normalTexture >= 0; });
  if (!mapped && spec.material.normal_strength != 1.0f)
    throw SceneError(
        spec.file,
        "material.normal_strength: no material of the scene has a normalTexture, so it "
        "would change nothing; remove the key or use a normal-mapped glTF");
  if (mapped && spec.material.normal_strength > 0.0f && spec::modeRule(spec.taa.mode).adaptive)
    throw SceneError(
        spec.file,
        "material.normal_strength: adaptive ray tracing shades its traced pixels without "
        "normal maps; set material.normal_strength to 0 or taa.mode to another mode");
}

// The tracer's shader indexes a fixed array of textures (scene/trace_textures.h).
void checkTraceTextures(const spec::CaseSpec& spec, const Scene& scene) {
  if (!spec::modeRule(spec.taa.mode).adaptive) return;
  const size_t used = traceTextureSlots(scene).textures.size();
  if (used > TRACE_MAX_TEXTURES)
    throw SceneError(spec.file, "taa.mode: adaptive ray tracing binds at most " +
                                    std::to_string(TRACE_MAX_TEXTURES) +
                                    " textures and the scene's materials use " +
                                    std::to_string(used) +
                                    " (base colour, emissive and occlusion maps); use a scene "
                                    "with fewer textures or another taa.mode");
}

// render.lod0 acts on textured materials, render.lod0_alpha_test on alpha-tested ones.
void checkLodMatching(const spec::CaseSpec& spec, const Scene& scene) {
  const auto any = [&](auto pred) {
    return std::any_of(scene.materials.begin(), scene.materials.end(), pred);
  };
  if (spec.render.lod0 &&
      !any([](const Material& m) { return m.baseColorTexture >= 0 || m.normalTexture >= 0; }))
    throw SceneError(spec.file,
                     "render.lod0: no material of the scene has a texture, so it would change "
                     "nothing; remove the key");
  if (spec.render.lod0_alpha_test && !any([&](const Material& m) {
        return m.alphaMode == AlphaMode::Mask && m.baseColorTexture >= 0;
      }))
    throw SceneError(
        spec.file,
        "render.lod0_alpha_test: no material of the scene is alpha-tested with a texture, "
        "so it would change nothing; remove the key or use such a scene (foliage)");
}

// debug.image: read once here, so a missing or unreadable file is a case problem (exit 2).
Image loadStillImage(const spec::CaseSpec& spec) {
  const std::filesystem::path path = resolve(spec, "debug.image", spec.debug.image);
  Image image;
  try {
    image = readImage(path);
  } catch (const std::exception& e) {
    throw SceneError(spec.file, std::string("debug.image: ") + e.what());
  }
  if (image.width != spec.render.width || image.height != spec.render.height)
    throw SceneError(spec.file, "debug.image: '" + spec.debug.image + "' is " +
                                    std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + " but the output is " +
                                    std::to_string(spec.render.width) + "x" +
                                    std::to_string(spec.render.height) +
                                    "; set render.width and render.height to the image's size");
  return image;
}
}  // namespace

Scene buildScene(const spec::CaseSpec& spec) {
  Scene scene;
  try {
    if (!spec.scene.gltf.empty()) {
      scene.models.push_back(loadGltf(resolve(spec, "scene.gltf", spec.scene.gltf), scene));
      selectAnimations(spec, "scene.animations", spec.scene.animations, scene.models.back());
    } else
      scene.models.push_back(buildProceduralScene(spec.scene.builtin, scene));
  } catch (const SceneError& e) {
    // Procedural errors know no file; name the case so the message is actionable.
    if (!spec.scene.gltf.empty()) throw;
    throw SceneError(spec.file, std::string("scene.builtin: ") + e.what());
  }
  for (size_t i = 0; i < spec.movers.size(); ++i) {
    const spec::MoverSpec& m = spec.movers[i];
    if (m.shape == spec::MoverShape::Gltf) {
      if (m.gltf.empty())
        throw SceneError(spec.file, "movers[" + std::to_string(i) +
                                        "]: shape is gltf but no gltf file is given");
      const std::string key = "movers[" + std::to_string(i) + "]";
      scene.models.push_back(loadGltf(resolve(spec, key + ".gltf", m.gltf), scene));
      selectAnimations(spec, key + ".animations", m.animations, scene.models.back());
    } else {
      scene.models.push_back(buildMoverShape(m.shape, m.color, scene));
    }
  }
  checkAlphaOverride(spec, scene);
  applyAlphaOverride(scene, spec.material.alpha_mode, spec.material.alpha_cutoff);
  checkNormalStrength(spec, scene);
  checkTraceTextures(spec, scene);
  checkLodMatching(spec, scene);
  if (!spec.debug.image.empty()) scene.still = loadStillImage(spec);
  return scene;
}

}  // namespace taa::scene
