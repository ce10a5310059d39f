// The report's path encoding: a file name with a space, '#', '?', '%' or a non-ASCII letter
// (a user's case named "fence #2", a folder in another script) must load the file it names.
#include "report/text_util.h"

#include <gtest/gtest.h>

namespace taa::report::text_util_test {
namespace {

TEST(EncodePath, EverythingButUnreservedCharactersAndSlashesIsPercentEncoded) {
  EXPECT_EQ(encodePath("fence_2/frame-0005.~v1.png"), "fence_2/frame-0005.~v1.png");
  EXPECT_EQ(encodePath("fence #2/a b?c%d.png"), "fence%20%232/a%20b%3Fc%25d.png");
  EXPECT_EQ(encodePath("zaun\xC3\xBC/\x7F\x01"), "zaun%C3%BC/%7F%01");  // UTF-8 bytes, DEL, SOH
}

}  // namespace
}  // namespace taa::report::text_util_test
