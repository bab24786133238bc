#include "teaching/expertise/execution_expertise.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "engine/core/error.hpp"

namespace sc {
namespace {

// waived[t][k]: Alg. 2's "missing" of trial t's k-th expert segment is not charged (see the header).
using Waivers = std::vector<std::vector<bool>>;

void check_reward(double reward, const std::string& where) {
  if (!std::isfinite(reward) || reward > 0.0)
    throw InputError(where, "execution reward " + std::to_string(reward) + " must be finite and <= 0");
}

void check(const ExecutionTrial& t, std::size_t index, std::size_t references) {
  const std::string where = "expertise trial " + std::to_string(index);
  if (t.segments.size() != t.trial.expert.segments.size())
    throw InputError(where, "execution scores must be given for each of the expert's segments");
  for (const SegmentExecution& s : t.segments) {
    check_reward(s.reward, where);
    if (s.reference_rewards.size() != references)
      throw InputError(where,
                       "every segment must be scored against the same " + std::to_string(references) + " references");
    for (double r : s.reference_rewards) check_reward(r, where);
  }
}

std::size_t reference_count(const std::vector<ExecutionTrial>& trials) {
  for (const ExecutionTrial& t : trials)
    if (!t.segments.empty()) return t.segments.front().reference_rewards.size();
  return 0;
}

// Whether reference r still scores above the expert, summed over all segments, without the skill where it
// gains most.
bool wins_without_its_best_skill(const std::vector<ExecutionTrial>& trials, std::size_t r) {
  std::map<int, double> gain;  // skill -> reference's sum minus expert's
  for (const ExecutionTrial& t : trials)
    for (std::size_t k = 0; k < t.segments.size(); ++k)
      gain[t.trial.expert.segments[k].skill] += t.segments[k].reference_rewards[r] - t.segments[k].reward;
  double total = 0.0, best = 0.0;
  for (const auto& [skill, g] : gain) {
    total += g;
    best = std::max(best, g);
  }
  return total - best > 0.0;
}

// The references whose scores have the highest means over every segment, at most kLearnerHands of them, each
// above the expert's own even without the skill where it gains most; best first.
std::vector<int> learners_hands(const std::vector<ExecutionTrial>& trials, std::size_t references) {
  std::vector<double> sums(references, 0.0);
  double expert = 0.0;
  for (const ExecutionTrial& t : trials)
    for (const SegmentExecution& s : t.segments) {
      expert += s.reward;
      for (std::size_t r = 0; r < references; ++r) sums[r] += s.reference_rewards[r];
    }
  std::vector<int> order(references);
  for (std::size_t r = 0; r < references; ++r) order[r] = static_cast<int>(r);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return sums[a] > sums[b]; });
  std::vector<int> out;
  for (int r : order)
    if (static_cast<int>(out.size()) < kLearnerHands && sums[static_cast<std::size_t>(r)] > expert &&
        wins_without_its_best_skill(trials, static_cast<std::size_t>(r)))
      out.push_back(r);
  return out;
}

// Reference `hand`'s name as the trials give it ("reference k" if they give none).
std::string hand_name(const std::vector<ExecutionTrial>& trials, int hand) {
  for (const ExecutionTrial& t : trials)
    if (static_cast<std::size_t>(hand) < t.reference_names.size())
      return t.reference_names[static_cast<std::size_t>(hand)];
  return "reference " + std::to_string(hand);
}

// Each segment's reward against the expert or the learner's hands, whichever is closest.
std::vector<ExecutionTrial> in_learners_hand(std::vector<ExecutionTrial> trials, const std::vector<int>& hands) {
  for (ExecutionTrial& t : trials)
    for (SegmentExecution& s : t.segments)
      for (int r : hands) s.reward = std::max(s.reward, s.reference_rewards[static_cast<std::size_t>(r)]);
  return trials;
}

// The largest penalty of `skill` over the trials, with where it happened.
TargetWhy why_of(int skill, const std::vector<ExecutionTrial>& trials, const Waivers& waived, ExpertiseMode mode,
                 bool repeated) {
  TargetWhy best;
  best.skill = skill;
  best.delta = -1.0;
  for (std::size_t t = 0; t < trials.size(); ++t) {
    const ExecutionTrial& et = trials[t];
    std::set<int> shown;
    for (const SkillSegment& s : et.trial.student.segments) shown.insert(s.skill);
    for (std::size_t k = 0; k < et.trial.expert.segments.size(); ++k) {
      const SkillSegment& e = et.trial.expert.segments[k];
      if (e.skill != skill) continue;
      const double j = static_cast<double>(k + 1);
      const double missing = shown.count(skill) || waived[t][k] ? 0.0 : -et.trial.student_reward / j;
      const double error = mode == ExpertiseMode::QualityAware ? -kExecutionWeight * et.segments[k].reward / j : 0.0;
      const double delta = std::max(missing, error);
      if (delta <= best.delta) continue;
      best = {skill,
              missing >= error ? TargetReason::Missing
              : repeated       ? TargetReason::RepeatedError
                               : TargetReason::LargeError,
              static_cast<int>(t),
              static_cast<int>(k + 1),
              delta,
              e.begin,
              e.end,
              et.segments[k].learner_begin,
              et.segments[k].learner_end};
    }
  }
  if (best.delta <= 0.0) {
    best.delta = 0.0;
    best.reason = TargetReason::NoMistake;
  }
  return best;
}

double median_of(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// The skills done worse than noise makes in every way a repetition can show (the header's repeated
// evidence): skill -> the repeated floor its segments are charged beyond.
std::map<int, double> repeatedly_worse(const std::vector<ExecutionTrial>& trials, const NoiseFloor& floor) {
  std::map<int, std::vector<double>> by_skill;
  for (const ExecutionTrial& t : trials)
    for (std::size_t k = 0; k < t.segments.size(); ++k)
      by_skill[t.trial.expert.segments[k].skill].push_back(t.segments[k].reward);
  std::map<int, double> out;
  for (const auto& [skill, rewards] : by_skill) {
    const std::optional<double> f = rewards.size() == 2               ? floor.repeated_twice
                                    : rewards.size() >= kRepeatedMore ? floor.repeated_more
                                                                      : std::nullopt;
    if (f && median_score(rewards) < *f) out[skill] = *f;
  }
  return out;
}

// Each segment's reward relative to the learner's usual spread: only the part below the outlier cut
// (median - kOutlierCut robust standard deviations) and the noise floor counts, so what stands out from how
// this learner does everything else, and from what noise does, is charged, and the ordinary scatter of a
// hand or a device is not. A skill done repeatedly worse than noise makes is charged beyond its repeated floor.
std::vector<ExecutionTrial> relative_to_learner(std::vector<ExecutionTrial> trials,
                                                const std::optional<NoiseFloor>& floor,
                                                const std::map<int, double>& repeated) {
  std::vector<double> rewards;
  for (const ExecutionTrial& t : trials)
    for (const SegmentExecution& s : t.segments) rewards.push_back(s.reward);
  if (rewards.empty()) return trials;
  const double median = median_of(rewards);
  std::vector<double> deviations;
  for (double r : rewards) deviations.push_back(std::abs(r - median));
  const double spread = kMadToStandardDeviation * median_of(deviations);
  const double cut = std::min(median - kOutlierCut * spread, floor ? floor->segment : 0.0);
  for (ExecutionTrial& t : trials)
    for (std::size_t k = 0; k < t.segments.size(); ++k) {
      const auto it = repeated.find(t.trial.expert.segments[k].skill);
      const double skill_cut = it == repeated.end() ? cut : std::max(cut, it->second);
      t.segments[k].reward = std::min(0.0, t.segments[k].reward - skill_cut);
    }
  return trials;
}

// The execution term: each segment's charge beyond its cut (relative_to_learner), weighted by 1 / j.
void add_execution_charges(ExpertiseEstimate& estimate, const std::vector<ExecutionTrial>& trials,
                           const std::map<int, double>& repeated) {
  for (std::size_t t = 0; t < trials.size(); ++t) {
    const ExecutionTrial& et = trials[t];
    for (std::size_t k = 0; k < et.segments.size(); ++k) {
      const int j = static_cast<int>(k + 1);
      const double q = et.segments[k].reward;
      if (q == 0.0) continue;
      const int m = et.trial.expert.segments[k].skill;
      const double delta = -kExecutionWeight * q / j;
      estimate.expertise[static_cast<std::size_t>(m)] -= delta;
      estimate.contributions[static_cast<std::size_t>(m)].push_back(
          {static_cast<int>(t), et.trial.scenario, j, q, delta, true, repeated.count(m) > 0});
    }
  }
}

Waivers missing_waivers(const std::vector<ExecutionTrial>& trials, ExpertiseMode mode,
                        const std::optional<NoiseFloor>& floor) {
  Waivers out;
  for (const ExecutionTrial& t : trials) {
    out.emplace_back(t.segments.size(), false);
    if (mode != ExpertiseMode::QualityAware || !floor) continue;
    for (std::size_t k = 0; k < t.segments.size(); ++k) out.back()[k] = t.segments[k].reward >= floor->segment;
  }
  return out;
}

void check_floor(const NoiseFloor& f) {
  for (const std::optional<double> v : {std::optional<double>(f.segment), f.repeated_twice, f.repeated_more})
    if (v && !(std::isfinite(*v) && *v <= 0.0))
      throw InputError("quality-aware expertise", "noise floor " + std::to_string(*v) + " must be <= 0");
}

// Takes back Alg. 2's penalties the waivers cancel. E_m is summed again from the penalties kept, in Alg. 2's
// order, so a skill whose every penalty was waived is exactly 0 (not a rounding residue that ranks it).
void waive_missing(ExpertiseEstimate& estimate, const Waivers& waived) {
  for (std::size_t m = 0; m < estimate.contributions.size(); ++m) {
    std::vector<ExpertiseContribution>& list = estimate.contributions[m];
    const auto cancelled = [&](const ExpertiseContribution& c) {
      return waived[static_cast<std::size_t>(c.trial)][static_cast<std::size_t>(c.position - 1)];
    };
    if (std::none_of(list.begin(), list.end(), cancelled)) continue;
    list.erase(std::remove_if(list.begin(), list.end(), cancelled), list.end());
    estimate.expertise[m] = 0.0;
    for (const ExpertiseContribution& c : list) estimate.expertise[m] -= c.delta;
  }
}

}  // namespace

const std::map<std::string, ExpertiseMode>& expertise_modes_by_name() {
  static const std::map<std::string, ExpertiseMode> modes{{"alg2", ExpertiseMode::Alg2},
                                                          {"quality-aware", ExpertiseMode::QualityAware}};
  return modes;
}

const std::string& expertise_mode_name(ExpertiseMode mode) {
  for (const auto& [name, m] : expertise_modes_by_name())
    if (m == mode) return name;
  throw std::logic_error("expertise mode without a name");
}

double median_score(std::vector<double> scores) {
  if (scores.empty()) throw InputError("quality-aware expertise", "no scores to take a median of");
  std::sort(scores.begin(), scores.end());
  const std::size_t n = scores.size();
  return n % 2 == 1 ? scores[n / 2] : 0.5 * (scores[n / 2 - 1] + scores[n / 2]);
}

const char* target_reason_words(TargetReason reason) {
  switch (reason) {
    case TargetReason::Missing:
      return "missing";
    case TargetReason::LargeError:
      return "done with a large error here";
    case TargetReason::NoMistake:
      return "no mistake seen";
    case TargetReason::RepeatedError:
      return "done a little wrong every time";
  }
  return "missing";
}

ExecutionExpertise estimate_execution_expertise(const std::vector<ExecutionTrial>& given_trials, int num_skills,
                                                int num_targets, ExpertiseMode mode,
                                                const std::optional<NoiseFloor>& noise_floor) {
  const std::size_t references = reference_count(given_trials);
  for (std::size_t t = 0; t < given_trials.size(); ++t) check(given_trials[t], t, references);
  if (noise_floor) check_floor(*noise_floor);
  ExecutionExpertise out;
  if (mode == ExpertiseMode::QualityAware) out.learner_hands = learners_hands(given_trials, references);
  const std::vector<ExecutionTrial> given = in_learners_hand(given_trials, out.learner_hands);
  // Repeated evidence only in the expert's hand (the header says why).
  const std::map<int, double> repeated = noise_floor && mode == ExpertiseMode::QualityAware && out.learner_hands.empty()
                                             ? repeatedly_worse(given, *noise_floor)
                                             : std::map<int, double>{};
  const std::vector<ExecutionTrial> trials = relative_to_learner(given, noise_floor, repeated);
  const Waivers waived = missing_waivers(given, mode, noise_floor);
  std::vector<ExpertiseTrial> plain;
  for (const ExecutionTrial& t : given) plain.push_back(t.trial);
  out.estimate = estimate_expertise(plain, num_skills, num_targets);
  if (mode == ExpertiseMode::QualityAware) {
    waive_missing(out.estimate, waived);
    add_execution_charges(out.estimate, trials, repeated);
    rank_expertise(out.estimate, num_targets);
  }
  for (int m : out.estimate.targets) out.why.push_back(why_of(m, trials, waived, mode, repeated.count(m) > 0));
  if (!out.learner_hands.empty()) out.estimate.learner_hand = hand_name(given_trials, out.learner_hands.front());
  return out;
}

}  // namespace sc
