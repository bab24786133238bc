#include "engine/review_view/review_palette.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <utility>

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

SkillPalette::SkillPalette(std::vector<int> skills) : skills_(std::move(skills)) {
  std::sort(skills_.begin(), skills_.end());
  skills_.erase(std::unique(skills_.begin(), skills_.end()), skills_.end());
}

Color SkillPalette::color(int skill, float alpha) const {
  const auto at = std::lower_bound(skills_.begin(), skills_.end(), skill);
  const bool listed = at != skills_.end() && *at == skill;
  const long slot = listed ? at - skills_.begin() : static_cast<long>(skills_.size()) + std::abs(skill);
  return Color::hex(kSkillColors[static_cast<std::size_t>(slot) % kSkillColors.size()], alpha);
}

ImU32 SkillPalette::color_u32(int skill, float alpha) const { return to_u32(color(skill, alpha)); }

ImU32 to_u32(Color color) { return color.packed_abgr(); }

}  // namespace sc::review_view
