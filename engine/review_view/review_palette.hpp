#pragma once
// Colours of the review pictures: one per skill (readable on the grey lot and on the light paper, and told
// apart by colour-blind viewers as far as 8 hues allow: the Okabe-Ito set, darkened where it vanished on
// the paper), and the before/after pair.
#include <imgui.h>

#include <vector>

#include "engine/render/draw_types.hpp"

namespace sc::review_view {

// Which hue each skill gets in one session's pictures. A hue by skill id alone (id mod 8) gave skills 6 and
// 14 of one parking session the same yellow, side by side in one trial. Here the skills a session can show
// (its expert pool's, in id order) take the hues in turn, so a pool of up to 8 skills never repeats one, and
// every picture of the session (trial, chart, legend) colours a skill alike. Skills outside the list follow
// on after it. Default-constructed: by id.
class SkillPalette {
 public:
  SkillPalette() = default;
  explicit SkillPalette(std::vector<int> skills);

  Color color(int skill, float alpha = 1.0f) const;
  ImU32 color_u32(int skill, float alpha = 1.0f) const;

 private:
  std::vector<int> skills_;  // sorted, unique
};

ImU32 to_u32(Color color);

inline constexpr Color kBefore = Color::hex(0xff8c42);  // pre-test: orange
inline constexpr Color kAfter = Color::hex(0x2ec4b6);   // evaluation: teal
inline constexpr Color kExpertRibbon = Color::hex(0xb9d6ff, 0.35f);
inline constexpr Color kGhostDrill = Color::hex(0xffffff, 0.85f);

}  // namespace sc::review_view
