// What makes a scene move, for the invariants that need a still one (no_ghosting's still
// frames, bit_stable, converges): a glTF mover's own animation moves it at speed 0 too.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "case/case_loader.h"
#include "invariants/invariant_support.h"

namespace {

std::string moverAtSpeedZero(const std::string& animationSpeed) {
  const std::string json = R"({"movers": [{"shape": "gltf", "gltf": "scenes/khronos/BoxAnimated.gltf",
                                 "speed": 0, "animation_speed": )" + animationSpeed + "}]}";
  const auto loaded =
      taa::cases::parseCase(json, std::filesystem::path(TAA_SOURCE_DIR) / "cases" / "what_moves.json");
  return taa::invariants::whatMoves(loaded.spec);
}

TEST(WhatMoves, AGltfMoverAtSpeedZeroMovesAtAnyAnimationSpeedAboveZero) {
  for (const char* speed : {"0.5", "1", "2"})
    EXPECT_NE(moverAtSpeedZero(speed).find(std::string("movers[0].animation_speed is ") + speed),
              std::string::npos)
        << moverAtSpeedZero(speed);
  EXPECT_EQ(moverAtSpeedZero("0"), "");
}

}  // namespace
