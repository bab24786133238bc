#pragma once
// Hand-made segmentations for the teaching-algorithm tests: consecutive segments from skill ids.
#include <utility>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc::test {

// Consecutive segments (skill, length) starting at step 0.
inline Segmentation segments_of(const std::vector<std::pair<int, int>>& parts) {
  Segmentation s;
  int t = 0;
  for (const auto& [skill, length] : parts) {
    s.segments.push_back({skill, t, t + length});
    t += length;
  }
  return s;
}

// Consecutive segments of the same length, one per skill id.
inline Segmentation segments_of(const std::vector<int>& skills, int length) {
  std::vector<std::pair<int, int>> parts;
  parts.reserve(skills.size());
  for (int skill : skills) parts.emplace_back(skill, length);
  return segments_of(parts);
}

}  // namespace sc::test
