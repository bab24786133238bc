#include "teaching/skills/skill_usage.hpp"

#include <map>

namespace sc {

SkillUsageSummary skill_usage(const std::vector<Segmentation>& segmentations) {
  std::map<int, SkillUsage> by_skill;
  SkillUsageSummary out;
  for (const Segmentation& s : segmentations)
    for (const SkillSegment& seg : s.segments) {
      SkillUsage& u = by_skill[seg.skill];
      u.skill = seg.skill;
      ++u.segments;
      u.steps += seg.length();
      ++out.segments;
      out.steps += seg.length();
    }
  for (const auto& [skill, usage] : by_skill) out.skills.push_back(usage);
  return out;
}

Json to_json(const SkillUsageSummary& usage) {
  Json per_skill = Json::array();
  for (const SkillUsage& u : usage.skills)
    per_skill.push_back({{"skill", u.skill},
                         {"segments", u.segments},
                         {"steps", u.steps},
                         {"mean_segment_length", u.mean_segment_length()}});
  return Json{{"skills_used", usage.skills_used()},
              {"segments", usage.segments},
              {"mean_segment_length", usage.mean_segment_length()},
              {"per_skill", std::move(per_skill)}};
}

}  // namespace sc
