#include "teaching/review/expertise_rounds.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "teaching/expertise/expertise_json.hpp"

namespace sc::review {

ExpertiseRounds expertise_rounds(const TaskKit& kit, const SessionRecord& record) {
  const int num_skills = kit.extractor().num_skills();
  ExpertiseRounds out;
  std::vector<ExpertiseEstimate> estimates;
  std::vector<std::vector<int>> targets;
  for (const auto& d : record.diagnoses) {
    const std::string where = "session " + std::to_string(record.session.id) + " diagnosis of round " + std::to_string(d.round);
    Json expertise, target;
    try {
      expertise = Json::parse(d.expertise_json);
      target = Json::parse(d.targets_json);
    } catch (const Json::exception& e) {
      throw InputError(where, std::string("is not JSON: ") + e.what());
    }
    ExpertiseEstimate estimate = expertise_from_json(JsonView(expertise, where));
    if (estimate.num_skills() != num_skills)
      throw InputError(where, "has " + std::to_string(estimate.num_skills()) + " skills, the " + kit.task() +
                                  " extractor has " + std::to_string(num_skills));
    std::vector<int> t;
    for (const auto& v : target) t.push_back(v.get<int>());
    out.rounds.push_back(d.round);
    estimates.push_back(std::move(estimate));
    targets.push_back(std::move(t));
  }
  for (int m = 0; m < num_skills; ++m) {
    SkillAcrossRounds skill;
    skill.skill = m;
    bool seen = false;
    for (std::size_t r = 0; r < estimates.size(); ++r) {
      const auto& e = estimates[r];
      const bool evidence = e.occurrences[static_cast<std::size_t>(m)] > 0;
      seen = seen || evidence;
      skill.expertise.push_back(evidence ? std::optional<double>(e.expertise[static_cast<std::size_t>(m)]) : std::nullopt);
      skill.targeted.push_back(std::find(targets[r].begin(), targets[r].end(), m) != targets[r].end());
      if (evidence) out.lowest = std::min(out.lowest, e.expertise[static_cast<std::size_t>(m)]);
    }
    if (!seen) continue;
    skill.description = kit.describe_skill(m);
    out.skills.push_back(std::move(skill));
  }
  return out;
}

}  // namespace sc::review
