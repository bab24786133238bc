#include "engine/review_view/review_palette.hpp"

#include <array>

namespace sc::review_view {
namespace {

constexpr std::array<std::uint32_t, 8> kSkillColors = {
    0xe69f00,  // orange
    0x2b9fe0,  // sky blue (darker than Okabe-Ito's 56b4e9 so it shows on the paper)
    0x009e73,  // bluish green
    0xd62f8a,  // reddish purple
    0xd55e00,  // vermillion
    0x0054a6,  // blue
    0xc9b800,  // yellow (darker: plain yellow is invisible on paper)
    0x6a3d9a,  // purple
};

}  // namespace

Color skill_color(int skill, float alpha) {
  const std::size_t i = static_cast<std::size_t>(skill < 0 ? -skill : skill) % kSkillColors.size();
  return Color::hex(kSkillColors[i], alpha);
}

ImU32 to_u32(Color color) { return color.packed_abgr(); }

ImU32 skill_color_u32(int skill, float alpha) { return to_u32(skill_color(skill, alpha)); }

}  // namespace sc::review_view
