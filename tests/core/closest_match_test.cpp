// "did you mean": the nearest candidate by edit distance, wherever it stands in the list, and
// nothing when every candidate is further than a typo (a third of the key, at least 2 edits).
#include "core/closest_match.h"

#include <gtest/gtest.h>

namespace taa::closest_match_test {
namespace {

TEST(ClosestMatch, TheNearestCandidateWhereverItStands) {
  const std::vector<std::string> keys = {"alpha", "alphas", "history_weight", "beta"};
  EXPECT_EQ(closestMatch("alpah", keys), "alpha");     // first of the list
  EXPECT_EQ(closestMatch("alphass", keys), "alphas");  // not the last
  EXPECT_EQ(closestMatch("histroy_weight", keys), "history_weight");
  EXPECT_EQ(closestMatch("gamma", keys), "");  // 4 edits from the nearest: no suggestion
  EXPECT_EQ(closestMatch("x", {}), "");
}

}  // namespace
}  // namespace taa::closest_match_test
