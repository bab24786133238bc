#include "teaching/learners/parking/planted_deficit_recovery.hpp"

#include <algorithm>

#include "teaching/tasks/diagnosis.hpp"

namespace sc {

double quiet_expertise_threshold(ExpertiseMode mode) {
  return mode == ExpertiseMode::Alg2 ? kQuietExpertiseAlg2 : kQuietExpertiseQualityAware;
}

std::vector<int> deficit_skills(PlantedDeficit deficit, const std::vector<ParkingSkillMotion>& motions) {
  std::vector<int> out;
  for (std::size_t m = 0; m < motions.size(); ++m) {
    const ParkingSkillMotion& s = motions[m];
    const bool spoiled = deficit == PlantedDeficit::NeverReversing ? motion_reverses(s)
                         : deficit == PlantedDeficit::WeakSteering ? s.sharp_fraction >= 0.5
                         : deficit == PlantedDeficit::LateBraking  ? motion_brakes(s)
                                                                   : false;
    if (spoiled) out.push_back(static_cast<int>(m));
  }
  return out;
}

std::vector<Json> planted_learner_trials(const ParkingKit& kit, const PlantedLearners& run, PlantedDeficit deficit,
                                         int learner) {
  const std::vector<int>& pretest = run.pretest;
  const Rng learner_rng = Rng(run.seed).fork(static_cast<std::uint64_t>(learner));
  Rng profile_rng = learner_rng;
  const DriveDevice device = static_cast<DriveDevice>(learner % 3);
  RealisticDriverProfile profile = sample_novice_profile(device, profile_rng);
  profile.deficit = deficit;
  profile.start_wait_s = run.start_wait_s;
  profile.end_wait_s = run.end_wait_s;
  profile.shift_for_gentle_steering = run.keyboard_shift && device == DriveDevice::Keyboard;
  std::vector<Json> trials;
  for (std::size_t k = 0; k < pretest.size(); ++k) {
    const Json& expert_doc = kit.expert_pool()[static_cast<std::size_t>(pretest[k])].trial;
    Rng drive_rng = learner_rng.fork(1 + k);
    const ParkingTrial expert = parse_parking_trial(expert_doc, "expert pool");
    if (run.keeps_trying)
      profile.keeps_trying_until_s = kit.time_limit_seconds(static_cast<int>(expert.actions.size()));
    trials.push_back(parking_trial_to_json(realistic_drive(expert, profile, drive_rng)));
  }
  return trials;
}

LearnerOutcome diagnose_planted_learner(const ParkingKit& kit, const PlantedLearners& run, PlantedDeficit deficit,
                                        ExpertiseMode mode, int learner) {
  const std::vector<Json> trials = planted_learner_trials(kit, run, deficit, learner);
  const Diagnosis d = diagnose_trials(kit, trials, run.seed, mode);
  LearnerOutcome out;
  out.targets = d.expertise.targets;
  const double n = std::max<double>(1.0, static_cast<double>(trials.size()));
  for (int m : out.targets) out.target_per_trial.push_back(d.expertise.expertise[static_cast<std::size_t>(m)] / n);
  for (int m : d.expertise.ranking)
    out.weakest_per_trial = std::min(out.weakest_per_trial, d.expertise.expertise[static_cast<std::size_t>(m)] / n);
  out.quiet = out.weakest_per_trial >= quiet_expertise_threshold(mode);
  const std::vector<int> spoiled = deficit_skills(deficit, kit.skill_motions());
  auto is_spoiled = [&](int m) { return std::find(spoiled.begin(), spoiled.end(), m) != spoiled.end(); };
  out.deficit_skills_seen =
      static_cast<int>(std::count_if(d.expertise.ranking.begin(), d.expertise.ranking.end(), is_spoiled));
  const int k = std::min({kTopTargets, out.deficit_skills_seen, static_cast<int>(out.targets.size())});
  out.recovered = k > 0 && std::all_of(out.targets.begin(), out.targets.begin() + k, is_spoiled);
  return out;
}

std::vector<RecoveryRow> planted_deficit_table(const ParkingKit& kit, const PlantedLearners& run, int learners) {
  std::vector<RecoveryRow> rows;
  for (PlantedDeficit deficit : {PlantedDeficit::None, PlantedDeficit::NeverReversing, PlantedDeficit::WeakSteering,
                                 PlantedDeficit::LateBraking}) {
    for (ExpertiseMode mode : {ExpertiseMode::Alg2, ExpertiseMode::QualityAware}) {
      RecoveryRow row{deficit, mode, learners, 0, 0, 0};
      const std::vector<int> spoiled = deficit_skills(deficit, kit.skill_motions());
      for (int i = 0; i < learners; ++i) {
        const LearnerOutcome o = diagnose_planted_learner(kit, run, deficit, mode, i);
        row.recovered += o.recovered;
        row.quiet += o.quiet;
        row.top1 += !o.targets.empty() && std::find(spoiled.begin(), spoiled.end(), o.targets.front()) != spoiled.end();
      }
      rows.push_back(row);
    }
  }
  return rows;
}

std::vector<double> noise_only_charge_rates(const ParkingKit& kit, const PlantedLearners& run, int learners) {
  std::vector<double> rates(static_cast<std::size_t>(kit.extractor().num_skills()), 0.0);
  for (int i = 0; i < learners; ++i) {
    const std::vector<Json> trials = planted_learner_trials(kit, run, PlantedDeficit::None, i);
    const std::vector<double>& e = diagnose_trials(kit, trials, run.seed, ExpertiseMode::Alg2).expertise.expertise;
    for (std::size_t m = 0; m < rates.size() && m < e.size(); ++m) rates[m] += e[m] < 0.0 ? 1.0 : 0.0;
  }
  for (double& r : rates) r /= std::max(1, learners);
  return rates;
}

}  // namespace sc
