#include "core/sha256.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "support/noise.h"

namespace taa {
namespace {

std::string hexOf(const std::string& text) {
  return sha256Hex(text.data(), text.size());
}

// Bytes that are a function of their index alone, so every length hashes distinct content.
std::vector<uint8_t> pattern(size_t size) {
  std::vector<uint8_t> out(size);
  for (size_t i = 0; i < size; ++i) out[i] = uint8_t(test::hash32(uint32_t(i)) >> 24);
  return out;
}

// FIPS 180-4's examples (NIST CSRC example values): a padded block, the two-block message
// whose padding needs a second block, the empty message and a long one.
TEST(Sha256, MatchesTheStandardsExamples) {
  EXPECT_EQ(hexOf(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(hexOf("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(hexOf("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(hexOf(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

// Bytes fed in uneven pieces hash as the whole: the buffered tail and the blocks taken
// straight from the caller's memory meet at every offset.
TEST(Sha256, PiecesHashAsTheWhole) {
  const std::vector<uint8_t> bytes = pattern(1000);
  const std::string whole = sha256Hex(bytes.data(), bytes.size());
  for (size_t piece : {1u, 3u, 63u, 64u, 65u, 127u, 200u}) {
    Sha256 h;
    for (size_t at = 0; at < bytes.size(); at += piece)
      h.update(bytes.data() + at, std::min(piece, bytes.size() - at));
    const auto digest = h.finish();
    EXPECT_EQ(toHex(digest.data(), digest.size()), whole) << "pieces of " << piece;
  }
}

// The SHA-extension compressor gives the portable one's state for every block count and
// starting state. Skipped where the CPU has no SHA extensions (its builds then use the portable
// compressor alone, which the examples above check).
TEST(Sha256, AcceleratedCompressorEqualsThePortableOne) {
  const sha256detail::Compress fast = sha256detail::compressAccelerated();
  if (!fast) GTEST_SKIP() << "this CPU has no SHA extensions";
  const std::vector<uint8_t> bytes = pattern(64 * 40);
  for (size_t blocks = 0; blocks <= 40; ++blocks) {
    uint32_t portable[8], accelerated[8];
    for (uint32_t i = 0; i < 8; ++i)
      portable[i] = accelerated[i] = 0x01234567u * (i + 1) + uint32_t(blocks);
    sha256detail::compressPortable(portable, bytes.data(), blocks);
    fast(accelerated, bytes.data(), blocks);
    EXPECT_EQ(0, std::memcmp(portable, accelerated, sizeof portable)) << blocks << " blocks";
  }
}

}  // namespace
}  // namespace taa
