#include "app/core/skill_colors.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

namespace sc::cli {

SkillColors::SkillColors(const Segmentation& segmentation) {
  for (const SkillSegment& seg : segmentation.segments)
    if (std::find(order_.begin(), order_.end(), seg.skill) == order_.end()) order_.push_back(seg.skill);
}

Color SkillColors::of(int skill) const {
  static constexpr std::array<std::uint32_t, 12> kPalette = {0xe6194b, 0x3cb44b, 0x4363d8, 0xf58231,
                                                             0x911eb4, 0x2bb5d8, 0xf032e6, 0x9a6324,
                                                             0x469990, 0x808000, 0xc2a000, 0x7f7f7f};
  const auto at = std::find(order_.begin(), order_.end(), skill);
  const auto i = static_cast<std::size_t>(at - order_.begin()) % kPalette.size();
  return Color::hex(kPalette[i]);
}

}  // namespace sc::cli
