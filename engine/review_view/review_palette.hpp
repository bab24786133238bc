#pragma once
// Colours of the review pictures: one per skill id (readable on the grey lot and on the light paper, and
// told apart by colour-blind viewers as far as 8 hues allow: the Okabe-Ito set, darkened where it vanished
// on the paper), and the before/after pair.
#include <imgui.h>

#include "engine/render/draw_types.hpp"

namespace sc::review_view {

Color skill_color(int skill, float alpha = 1.0f);  // cycles after 8 skills
ImU32 skill_color_u32(int skill, float alpha = 1.0f);
ImU32 to_u32(Color color);

inline constexpr Color kBefore = Color::hex(0xff8c42);  // pre-test: orange
inline constexpr Color kAfter = Color::hex(0x2ec4b6);   // evaluation: teal
inline constexpr Color kExpertRibbon = Color::hex(0xb9d6ff, 0.35f);
inline constexpr Color kGhostDrill = Color::hex(0xffffff, 0.85f);

}  // namespace sc::review_view
