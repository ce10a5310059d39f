// CPU cost of skinning and morphing (renderer/scene/deform.cpp), which the draw list
// pays twice a frame per deformed mesh (this frame's pose and the previous one).
// items_per_second: vertices deformed per second. A synthetic mesh of state.range(0) vertices, each
// with four joint influences, or two morph targets with normals.
//
//   build/bench/taa_bench --benchmark_filter=Deform
#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.h"

namespace {

using namespace taa::scene;

Scene syntheticMesh(size_t vertices, bool skinned, int targets) {
  Scene s;
  Mesh mesh;
  mesh.vertexCount = uint32_t(vertices);
  for (size_t i = 0; i < vertices; ++i) {
    const float x = float(i % 97) * 0.01f, y = float(i / 97) * 0.01f;
    s.vertices.push_back({{x, y, 0.0f}, {0.0f, 0.0f, 1.0f}, {x, y}, glm::vec4(1.0f)});
    if (skinned)
      mesh.skin.push_back({glm::uvec4(i % 8, (i + 1) % 8, (i + 2) % 8, (i + 3) % 8),
                           glm::vec4(0.4f, 0.3f, 0.2f, 0.1f)});
  }
  for (int t = 0; t < targets; ++t) {
    MorphTarget mt;
    mt.position.assign(vertices, glm::vec3(0.0f, 0.01f * float(t + 1), 0.0f));
    mt.normal.assign(vertices, glm::vec3(0.01f, 0.0f, 0.0f));
    mesh.targets.push_back(std::move(mt));
  }
  mesh.weights.assign(size_t(targets), 0.5f);
  s.meshes.push_back(std::move(mesh));
  return s;
}

void run(benchmark::State& state, bool skinned, int targets) {
  const auto n = size_t(state.range(0));
  const Scene s = syntheticMesh(n, skinned, targets);
  MeshDraw draw;
  draw.mesh = 0;
  draw.weights.assign(size_t(targets), 0.5f);
  if (skinned)
    for (int j = 0; j < 8; ++j)
      draw.joints.push_back(glm::rotate(glm::mat4(1.0f), 0.1f * float(j), glm::vec3(0, 0, 1)));
  for (auto _ : state) benchmark::DoNotOptimize(deformVertices(s, draw));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(n));
}

void BM_DeformSkin4(benchmark::State& state) {
  run(state, true, 0);
}
void BM_DeformMorph2(benchmark::State& state) {
  run(state, false, 2);
}
void BM_DeformMorph2Skin4(benchmark::State& state) {
  run(state, true, 2);
}

BENCHMARK(BM_DeformSkin4)->Arg(10000)->Arg(100000);
BENCHMARK(BM_DeformMorph2)->Arg(10000)->Arg(100000);
BENCHMARK(BM_DeformMorph2Skin4)->Arg(10000)->Arg(100000);

}  // namespace
