#include "teaching/review/expertise_rounds.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "teaching/curricula/curriculum_json.hpp"
#include "teaching/expertise/expertise_json.hpp"

namespace sc::review {
namespace {

// The skills the round's played practice drilled (none for a round without a stored curriculum).
std::vector<int> drilled_in_round(const SessionRecord& record, int round) {
  for (const records::CurriculumRecord& stored : record.curricula) {
    if (stored.round != round) continue;
    const std::string where =
        "session " + std::to_string(record.session.id) + " curriculum of round " + std::to_string(round);
    const Json doc = parse_json_text(stored.items_json, where);
    std::vector<int> played;
    for (const records::StoredTrial* t : record.trials_of(records::TrialKind::Practice, round))
      if (t->record.drill_index) played.push_back(*t->record.drill_index);
    std::vector<int> out;
    for (const auto& [skill, trials] : practice_trials_per_skill(curriculum_from_json(JsonView(doc, where)), played))
      out.push_back(skill);
    return out;
  }
  return {};
}

}  // namespace

ExpertiseRounds expertise_rounds(const TaskKit& kit, const SessionRecord& record) {
  const int num_skills = kit.extractor().num_skills();
  ExpertiseRounds out;
  std::vector<ExpertiseEstimate> estimates;
  std::vector<std::vector<int>> drilled;
  for (const auto& d : record.diagnoses) {
    const std::string where =
        "session " + std::to_string(record.session.id) + " diagnosis of round " + std::to_string(d.round);
    Json expertise;
    try {
      expertise = Json::parse(d.expertise_json);
    } catch (const Json::exception& e) {
      throw InputError(where, std::string("is not JSON: ") + e.what());
    }
    ExpertiseEstimate estimate = expertise_from_json(JsonView(expertise, where));
    if (estimate.num_skills() != num_skills)
      throw InputError(where, "has " + std::to_string(estimate.num_skills()) + " skills, the " + kit.task() +
                                  " extractor has " + std::to_string(num_skills));
    out.rounds.push_back(d.round);
    estimates.push_back(std::move(estimate));
    drilled.push_back(drilled_in_round(record, d.round));
  }
  for (int m = 0; m < num_skills; ++m) {
    SkillAcrossRounds skill;
    skill.skill = m;
    bool seen = false;
    for (std::size_t r = 0; r < estimates.size(); ++r) {
      const auto& e = estimates[r];
      const bool evidence = e.occurrences[static_cast<std::size_t>(m)] > 0;
      seen = seen || evidence;
      skill.expertise.push_back(evidence ? std::optional<double>(e.expertise[static_cast<std::size_t>(m)])
                                         : std::nullopt);
      skill.drilled.push_back(std::find(drilled[r].begin(), drilled[r].end(), m) != drilled[r].end());
      if (evidence) out.lowest = std::min(out.lowest, e.expertise[static_cast<std::size_t>(m)]);
    }
    if (!seen) continue;
    skill.description = kit.describe_skill(m);
    out.skills.push_back(std::move(skill));
  }
  return out;
}

}  // namespace sc::review
