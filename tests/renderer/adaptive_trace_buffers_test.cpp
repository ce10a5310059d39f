// The tracer's buffers hold what its geometry needs and no more: the static BVH and two nodes
// per mover triangle (rebuilt each frame), one triangle and one shading record per triangle,
// one record per material. The run log reports their sizes with the counts they come from.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "common/shared.h"
#include "support/process.h"

namespace taa::adaptive_trace_buffers_test {
namespace {

namespace fs = std::filesystem;

// The repository's case `name` (a built-in scene, so nothing to resolve beside it), two frames
// long, with no goldens.
std::string twoFrames(const std::string& name) {
  std::ifstream in(fs::path(TAA_SOURCE_DIR) / "cases" / (name + ".json"));
  auto j = nlohmann::json::parse(in);
  j["script"]["frames"] = 2;
  j["output"]["frames"] = {1};
  j["checks"] = {{"golden", false}};
  const fs::path dir = fs::path(TAA_TEST_OUT) / "adaptive-trace-buffers";
  fs::create_directories(dir);
  std::ofstream(dir / (name + ".json")) << j.dump(1);
  return (dir / (name + ".json")).string();
}

TEST(AdaptiveTraceBuffers, EachBufferIsItsCountTimesItsRecord) {
  int withMovers = 0;
  for (const char* name : {"adaptive_wires", "adaptive_trace_disoccluded"}) {
    SCOPED_TRACE(name);
    const auto r = test::runHarness("render " + twoFrames(name) + " --out " + TAA_TEST_OUT +
                                    "/adaptive-trace-buffers/out");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::smatch m;
    const std::regex line(
        "(\\d+) static triangles \\((\\d+) BVH nodes\\), (\\d+) mover triangles[^;]*; buffers: "
        "BVH (\\d+) B, triangles (\\d+) B, shading (\\d+) B, materials (\\d+) B");
    ASSERT_TRUE(std::regex_search(r.output, m, line)) << r.output;
    const auto n = [&](int i) { return std::stoull(m[i].str()); };
    const uint64_t statics = n(1), nodes = n(2), movers = n(3);
    const uint64_t triangles = std::max<uint64_t>(statics + movers, 1);
    EXPECT_EQ(n(4), std::max<uint64_t>(nodes + 2 * movers, 1) * sizeof(gpu::BvhNode));
    EXPECT_EQ(n(5), triangles * sizeof(gpu::TraceTriangle));
    EXPECT_EQ(n(6), triangles * sizeof(gpu::TraceShading));
    EXPECT_GT(n(7), 0u);
    EXPECT_EQ(n(7) % sizeof(gpu::TraceMaterial), 0u);
    withMovers += movers > 0;
  }
  EXPECT_EQ(withMovers, 1);  // the second case's movers are traced too
}

}  // namespace
}  // namespace taa::adaptive_trace_buffers_test
