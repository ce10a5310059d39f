// Two workers asking for one reference at once: the second waits for the first's render
// instead of rendering it again (api/reference_cache.h, ReferenceCache::Claim).
#include <gtest/gtest.h>

#include <thread>

#include "api/reference_cache.h"

namespace taa {
namespace {

// Until `cache` has `n` threads waiting in findOrClaim (bounded: a cache that never waits
// fails the test instead of hanging it).
bool untilWaiting(const ReferenceCache& cache, size_t n) {
  for (int i = 0; i < 200000 && cache.waiting() < n; ++i) std::this_thread::yield();
  return cache.waiting() == n;
}

TEST(ReferenceClaim, ASecondAskerWaitsForTheFirstsRenderAndRendersNothing) {
  ReferenceCache cache;
  auto first = cache.findOrClaim("k");
  ASSERT_FALSE(first.image);
  ASSERT_TRUE(first.claim);
  ReferenceCache::Lookup second;
  std::thread asker([&] { second = cache.findOrClaim("k"); });
  EXPECT_TRUE(untilWaiting(cache, 1)) << "the second asker did not wait for the claimed key";
  first.claim.fulfil(Image(2, 2, 4, 0.5f));
  asker.join();
  ASSERT_TRUE(second.image);
  EXPECT_FALSE(second.claim);
  EXPECT_EQ(second.image->data[0], 0.5f);
  EXPECT_EQ(cache.stats().rendered, 1u);
  EXPECT_EQ(cache.stats().reused, 1u);
  // Another key never waits for this one.
  auto other = cache.findOrClaim("other");
  EXPECT_TRUE(other.claim);
}

TEST(ReferenceClaim, AClaimDroppedUnfulfilledLetsTheWaiterRender) {
  ReferenceCache cache;
  ReferenceCache::Lookup second;
  {
    auto first = cache.findOrClaim("k");  // its frame throws before the reference is read
    std::thread asker([&] { second = cache.findOrClaim("k"); });
    EXPECT_TRUE(untilWaiting(cache, 1));
    first = {};
    asker.join();
  }
  EXPECT_FALSE(second.image);
  ASSERT_TRUE(second.claim);
  second.claim.fulfil(Image(1, 1, 4, 2.0f));
  EXPECT_EQ(cache.find("k")->data[0], 2.0f);
  EXPECT_EQ(cache.stats().rendered, 1u);
}

// --no-reference-cache keeps nothing: every asker renders, none waits for another.
TEST(ReferenceClaim, ACacheThatKeepsNothingMakesNoOneWait) {
  ReferenceCache none(0);
  auto first = none.findOrClaim("k");
  auto second = none.findOrClaim("k");  // would wait forever if claims held here
  ASSERT_TRUE(first.claim);
  ASSERT_TRUE(second.claim);
  first.claim.fulfil(Image(1, 1, 4, 1.0f));
  second.claim.fulfil(Image(1, 1, 4, 1.0f));
  EXPECT_EQ(none.stats().rendered, 2u);  // the closing line still counts them
  EXPECT_EQ(none.find("k"), nullptr);
}

}  // namespace
}  // namespace taa
