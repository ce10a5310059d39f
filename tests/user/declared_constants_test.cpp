// The constants a shader's source declares, read from its preprocessed text: both languages'
// spellings, their types and ids, and nothing the header owns or a longer name merely contains.
#include "user/declared_constants.h"

#include <gtest/gtest.h>

namespace taa::user {
namespace {

TEST(DeclaredConstants, BothLanguagesSpellingsWithTheirTypes) {
  const auto c = declaredConstants(
      "layout(constant_id = 3) const float alpha = 0.1;\n"
      "layout (constant_id=4) const int taps=2;\n"
      "[[vk::constant_id(5)]] const bool clip = true;\n"
      "[[vk::constant_id(6)]]\nstatic const uint count = 4;\n"
      "layout(constant_id = 0) const uint taa_local_size_x = 8;\n"  // the header's own
      "int my_constant_id = 3;\n"                                   // a longer name
      "layout(constant_id = 7) const vec3 v = vec3(1);\n"          // no scalar: not one of ours
      "layout(constant_id = ID) const float unnumbered = 1.0;\n");  // an id glslang will refuse
  ASSERT_EQ(c.size(), 5u);
  EXPECT_EQ(c[0].name, "alpha");
  EXPECT_EQ(c[0].type, ParamType::Float);
  EXPECT_EQ(c[1].name, "taps");
  EXPECT_EQ(c[1].type, ParamType::Int);
  EXPECT_EQ(c[2].name, "clip");
  EXPECT_EQ(c[2].type, ParamType::Bool);
  EXPECT_EQ(c[3].name, "count");
  EXPECT_EQ(c[3].type, ParamType::Uint);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(c[size_t(i)].id, i + 3) << c[size_t(i)].name;
  EXPECT_EQ(c[4].name, "unnumbered");
  EXPECT_EQ(c[4].id, -1);  // the header's "not a number", not an id of its own
}

TEST(DeclaredConstants, HostileTextStaysBoundedAndLinear) {
  // Many qualifiers with no declarator near them: each is looked at within its window only.
  std::string text;
  for (int i = 0; i < 200000; ++i) text += "constant_id ";
  text += ")" + std::string(1 << 20, 'a') + "=";
  EXPECT_TRUE(declaredConstants(text).empty());
  std::string many;
  for (int i = 0; i < 500; ++i)
    many += "[[vk::constant_id(1)]] const float c" + std::to_string(i) + " = 1;\n";
  EXPECT_EQ(declaredConstants(many).size(), kMaxDeclaredConstants);
}

// An id of any length reads as itself up to the cap and as the cap past it: never as a
// prefix of what was written (1500000000000000 read as 1500000000000 before).
TEST(DeclaredConstants, AHugeIdSaturatesAtTheCap) {
  const auto c = declaredConstants(
      "layout(constant_id = 1099511627775) const float a = 1.0;\n"
      "layout(constant_id = 1500000000000000) const float b = 1.0;\n"
      "layout(constant_id = 99999999999999999999999999) const float c = 1.0;\n");
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].id, kConstantIdCap - 1);
  EXPECT_EQ(c[1].id, kConstantIdCap);
  EXPECT_EQ(c[2].id, kConstantIdCap);
}

}  // namespace
}  // namespace taa::user
