#include "api/tracks.h"

#include <utility>

#include "script/track_bake.h"
#include "script/tracks.h"

namespace taa {

CaseTracks readCaseTracks(const spec::CaseSpec& spec) {
  CaseTracks out;
  if (!script::usesTracks(spec)) return out;
  auto tracks = std::make_shared<const script::Tracks>(script::loadTracks(spec));
  const std::pair<bool, const char*> lens[] = {{tracks->cameraHasFov, "fov_y_deg"},
                                               {tracks->cameraHasNear, "near"},
                                               {tracks->cameraHasFar, "far"}};
  for (const auto& [carried, key] : lens)
    if (carried) out.lensKeys.push_back(key);
  out.tracks = std::move(tracks);
  return out;
}

std::string bakeCaseTrack(const spec::CaseSpec& spec, const std::string& description) {
  return script::bakeTrackJson(spec, description);
}

}  // namespace taa
