#include "teaching/review/diagnosis_explained.hpp"

#include <cmath>

#include "engine/core/error.hpp"
#include "teaching/expertise/expertise_json.hpp"
#include "teaching/sessions/session_analysis.hpp"

namespace sc::review {
namespace {

const records::DiagnosisRecord& first_diagnosis(const SessionRecord& record) {
  for (const auto& d : record.diagnoses)
    if (d.round == 1) return d;
  throw InputError("session " + std::to_string(record.session.id), "has no diagnosis yet (the pre-test is unfinished)");
}

// The pre-test trial's expert segmentation, with the pool index as scenario id, as the trainer built it.
TestTrial test_trial_of(const SessionReview& review, const records::StoredTrial& t) {
  const Json scenario = Json::parse(t.record.scenario_json);
  const auto& pool = review.kit().expert_pool();
  TestTrial test;
  test.trial = Json::parse(t.record.trajectory_json);
  for (std::size_t i = 0; i < pool.size(); ++i)
    if (pool[i].scenario == scenario) {
      test.scenario = static_cast<int>(i);
      test.expert = pool[i].skills;
      test.expert_steps = pool[i].steps;
      return test;
    }
  // Not in the pool (another pool version): segment the expert's trial for it now.
  test.scenario = -1;
  test.expert_steps = review.kit().steps_of(review.expert_for(scenario));
  test.expert = review.kit().extractor().extract(test.expert_steps);
  return test;
}

// The trial and steps of `skill`'s largest penalty, if it has one.
std::optional<SkillPlace> place_of(const SessionReview& review, const std::vector<TestTrial>& tests,
                                   const std::vector<const records::StoredTrial*>& pretest,
                                   const PlacedDiagnosis& placed, int skill) {
  const TargetWhy* why = charged_why(placed, skill);
  if (!why) return std::nullopt;
  const auto t = static_cast<std::size_t>(why->trial);
  const int index = tests.at(t).scenario;
  const Json expert = index >= 0 ? review.kit().expert_pool().at(static_cast<std::size_t>(index)).trial
                                 : review.expert_for(Json::parse(pretest.at(t)->record.scenario_json));
  return SkillPlace{pretest.at(t)->seq,
                    why->learner_begin,
                    why->learner_end,
                    placed.learner_steps.at(t),
                    why->reason,
                    tests[t].trial,
                    expert};
}

}  // namespace

DiagnosisExplanation explain_diagnosis(const SessionReview& review) {
  const SessionRecord& record = review.record();
  const std::string where = "session " + std::to_string(record.session.id);
  const auto pretest = record.trials_of(records::TrialKind::Pretest);
  if (pretest.empty()) throw InputError(where, "has no pre-test trials");
  const records::DiagnosisRecord& stored = first_diagnosis(record);

  std::vector<TestTrial> tests;
  try {
    for (const auto* t : pretest) tests.push_back(test_trial_of(review, *t));
  } catch (const Json::exception& e) {
    throw InputError(where, std::string("has a pre-test trial that is not JSON: ") + e.what());
  }
  const PlacedDiagnosis placed = diagnosis_with_places(review.kit(), tests);
  const ExpertiseEstimate& now = placed.expertise.estimate;
  ExpertiseEstimate before;
  std::vector<int> stored_targets;  // the trainer's own record of its choice (the targets column)
  try {
    const Json doc = Json::parse(stored.expertise_json);
    before = expertise_from_json(JsonView(doc, where + " diagnosis"));
    for (const auto& v : Json::parse(stored.targets_json)) stored_targets.push_back(v.get<int>());
  } catch (const Json::exception& e) {
    throw InputError(where + " diagnosis", std::string("is not valid: ") + e.what());
  }

  DiagnosisExplanation out;
  out.round = 1;
  out.extractor = stored.extractor;
  out.mode = review.kit().learners_expertise();
  out.pretest_trials = static_cast<int>(pretest.size());
  out.learner_hand = now.learner_hand;
  out.hand_traces = learner_hand_traces(review.kit(), Json::parse(pretest.front()->record.scenario_json),
                                        tests.front().expert_steps, tests.front().trial, now.learner_hand);
  out.recomputed_targets = now.targets;
  out.stored_targets = stored_targets;
  out.matches_stored = now.num_skills() == before.num_skills() && stored_targets == now.targets;
  for (int m = 0; out.matches_stored && m < now.num_skills(); ++m)
    out.matches_stored =
        std::fabs(now.expertise[static_cast<std::size_t>(m)] - before.expertise[static_cast<std::size_t>(m)]) <= 1e-9;

  for (int m : out.stored_targets) {
    if (m < 0 || m >= now.num_skills())
      throw InputError(where + " diagnosis", "targets unknown skill " + std::to_string(m));
    SkillExplanation s;
    s.skill = m;
    s.description = review.kit().describe_skill(m);
    s.expertise = now.expertise[static_cast<std::size_t>(m)];
    s.occurrences = now.occurrences[static_cast<std::size_t>(m)];
    for (const ExpertiseContribution& c : now.contributions[static_cast<std::size_t>(m)])
      s.missed.push_back(
          {pretest[static_cast<std::size_t>(c.trial)]->seq, c.position, c.reward, c.delta, c.execution, c.repeated});
    s.place = place_of(review, tests, pretest, placed, m);
    out.skills.push_back(std::move(s));
  }
  return out;
}

}  // namespace sc::review
