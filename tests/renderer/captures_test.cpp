// The capture vocabulary (api/captures.h) is the one list both sides of the renderer/harness
// wall read: its names must not collide except where the read-back deliberately shares a
// target with the case's output.aux, and a record's captures must reach an invariant's view
// under the enumerator that names them.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "api/captures.h"
#include "api/frame_record.h"
#include "invariants/invariant.h"
#include "spec/render_spec.h"

namespace taa {
namespace {

static_assert(kCaptureCount <= 64, "CaptureSet (core/enum_set.h) holds 64 captures");

TEST(Captures, NamesAreUniqueAndIndexTheirRow) {
  std::set<std::string> names;
  for (size_t i = 0; i < kCaptureCount; ++i) {
    const CaptureInfo& c = kCaptures[i];
    EXPECT_EQ(size_t(c.capture), i) << c.name;
    EXPECT_TRUE(names.insert(c.name).second) << "two captures named " << c.name;
    EXPECT_NE(std::string(c.doc), "") << c.name;
  }
}

// frame_readback.cpp reads velocity and material_id once for output.aux and the capture
// alike; any other shared name would hand an invariant the wrong image.
TEST(Captures, OnlyTheSharedTargetsShareAnOutputAuxName) {
  std::set<std::string> shared;
  for (const auto& aux : spec::enumNames(spec::AuxBuffer{}))
    for (const CaptureInfo& c : kCaptures)
      if (aux.name == std::string(c.name)) shared.insert(c.name);
  EXPECT_EQ(shared, (std::set<std::string>{"velocity", "material_id"}));
}

TEST(Captures, SetHoldsWhatWasAdded) {
  CaptureSet s;
  EXPECT_TRUE(s.empty());
  s |= {Capture::Ids};
  s |= CaptureSet{Capture::EdgeMask};
  EXPECT_TRUE(s.has(Capture::Ids));
  EXPECT_TRUE(s.has(Capture::EdgeMask));
  EXPECT_FALSE(s.has(Capture::Reference));
  EXPECT_EQ(s, (CaptureSet{Capture::EdgeMask, Capture::Ids}));
  EXPECT_NE(s, CaptureSet{Capture::Ids});
}

TEST(Captures, RecordReachesTheViewByEnumerator) {
  FrameRecord r;
  r.frame = 4;
  r.hasImages = true;
  r.color = Image(2, 2, 4, 0.5f);
  r.aux.push_back({"depth", Image(2, 2, 1, 0.25f)});
  r.aux.push_back({captureName(Capture::Velocity), Image(2, 2, 2, 1.5f)});
  const invariants::FrameView without = invariants::FrameView::of(r);
  EXPECT_EQ(without.capture(Capture::Reference), nullptr);  // hasReference is false
  r.hasReference = true;
  r.reference = Image(2, 2, 4, 0.75f);
  const invariants::FrameView v = invariants::FrameView::of(r);
  EXPECT_EQ(v.frame, 4);
  EXPECT_EQ(v.output, &r.color);
  EXPECT_EQ(v.capture(Capture::Reference), &r.reference);
  EXPECT_EQ(v.capture(Capture::Velocity), &r.aux[1].image);
  for (Capture absent : {Capture::Current, Capture::Ids, Capture::Resolved,
                         Capture::Segmentation, Capture::Cmaa, Capture::EdgeMask})
    EXPECT_EQ(v.capture(absent), nullptr) << captureName(absent);
}

}  // namespace
}  // namespace taa
