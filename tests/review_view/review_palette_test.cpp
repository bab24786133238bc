#include "engine/review_view/review_palette.hpp"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace sc::review_view {
namespace {

std::set<ImU32> colours_of(const SkillPalette& palette, const std::vector<int>& skills) {
  std::set<ImU32> out;
  for (int skill : skills) out.insert(palette.color_u32(skill));
  return out;
}

TEST(SkillPalette, EightSkillsOfAPoolNeverShareAHue) {
  // A parking session's skills: by id alone 6 and 14 share a hue (id mod 8).
  const std::vector<int> pool = {14, 0, 5, 6, 7, 10, 11, 12, 6};
  EXPECT_LT(colours_of(SkillPalette(), pool).size(), 8u);
  EXPECT_EQ(colours_of(SkillPalette(pool), pool).size(), 8u);
}

TEST(SkillPalette, ASkillKeepsItsColourWhateverOrderThePoolIsListedIn) {
  const SkillPalette a({3, 9, 1}), b({9, 1, 3, 3});
  for (int skill : {1, 3, 9, 4, 20}) EXPECT_EQ(a.color_u32(skill), b.color_u32(skill)) << skill;
}

TEST(SkillPalette, SkillsOutsideThePoolStillGetAColourAndAlphaIsKept) {
  const SkillPalette palette({2, 4});
  EXPECT_NE(palette.color_u32(2), palette.color_u32(4));
  EXPECT_NO_THROW(palette.color(-3));
  EXPECT_FLOAT_EQ(palette.color(17, 0.25f).a, 0.25f);
  EXPECT_EQ(palette.color(17, 0.25f).with_alpha(1.0f).packed_abgr(), palette.color_u32(17));
}

}  // namespace
}  // namespace sc::review_view
