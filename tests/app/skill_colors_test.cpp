// Colours of `segment --png`: by first appearance in the picture, distinct for up to 12 skills.
#include "app/core/skill_colors.hpp"

#include <gtest/gtest.h>

#include <tuple>

namespace sc::cli {
namespace {

auto rgb(const Color& c) { return std::make_tuple(c.r, c.g, c.b); }

Segmentation of_skills(const std::vector<int>& skills) {
  Segmentation s;
  int t = 0;
  for (int skill : skills) {
    s.segments.push_back({skill, t, t + 5});
    t += 5;
  }
  return s;
}

TEST(SkillColors, FirstAppearanceDecidesTheColourNotTheSkillId) {
  const SkillColors a(of_skills({21, 18, 21, 3})), b(of_skills({7, 2, 7, 11}));
  // The first skill of each picture gets the same colour, whatever its id; so do the second and third.
  EXPECT_EQ(rgb(a.of(21)), rgb(b.of(7)));
  EXPECT_EQ(rgb(a.of(18)), rgb(b.of(2)));
  EXPECT_EQ(rgb(a.of(3)), rgb(b.of(11)));
  EXPECT_NE(rgb(a.of(21)), rgb(a.of(18)));
  EXPECT_EQ(rgb(a.of(21)), rgb(Color::hex(0xe6194b)));  // the palette's first (red)
}

TEST(SkillColors, TwelveSkillsGetTwelveColoursThenTheyCycle) {
  std::vector<int> skills;
  for (int i = 0; i < 13; ++i) skills.push_back(100 - i);
  const SkillColors colors(of_skills(skills));
  for (int i = 0; i < 12; ++i)
    for (int j = i + 1; j < 12; ++j) EXPECT_NE(rgb(colors.of(skills[i])), rgb(colors.of(skills[j]))) << i << " " << j;
  EXPECT_EQ(rgb(colors.of(skills[12])), rgb(colors.of(skills[0])));
}

TEST(SkillColors, ASkillNotInThePictureGetsTheNextColour) {
  const SkillColors colors(of_skills({4, 9}));
  const SkillColors three(of_skills({4, 9, 5}));
  EXPECT_EQ(rgb(colors.of(42)), rgb(three.of(5)));
}

}  // namespace
}  // namespace sc::cli
