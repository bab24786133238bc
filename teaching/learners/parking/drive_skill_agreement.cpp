#include "teaching/learners/parking/drive_skill_agreement.hpp"

#include <algorithm>
#include <cmath>

#include "teaching/tasks/parking_steps.hpp"

namespace sc {

std::vector<int> skill_per_step(const Segmentation& segmentation, int length) {
  std::vector<int> out(static_cast<std::size_t>(std::max(length, 0)), -1);
  for (const SkillSegment& s : segmentation.segments)
    for (int t = std::max(s.begin, 0); t < s.end && t < length; ++t) out[static_cast<std::size_t>(t)] = s.skill;
  return out;
}

StepAgreement step_agreement(const Segmentation& clean, int clean_length, const Segmentation& driven, int driven_length,
                             int shift) {
  const std::vector<int> a = skill_per_step(clean, clean_length);
  const std::vector<int> b = skill_per_step(driven, driven_length);
  StepAgreement out;
  for (int t = 0; t < clean_length && t + shift < driven_length; ++t) {
    if (t + shift < 0) continue;
    ++out.steps;
    out.agreed += a[static_cast<std::size_t>(t)] == b[static_cast<std::size_t>(t + shift)];
  }
  return out;
}

SkillPresence skill_presence(const Segmentation& clean, const Segmentation& driven) {
  std::vector<int> expert = clean.skills(), copy = driven.skills();
  std::sort(expert.begin(), expert.end());
  expert.erase(std::unique(expert.begin(), expert.end()), expert.end());
  SkillPresence out;
  out.skills = static_cast<int>(expert.size());
  for (int m : expert) out.present += std::find(copy.begin(), copy.end(), m) != copy.end();
  return out;
}

std::vector<DriveCondition> standard_drive_conditions() {
  auto profile = [](DriveDevice device, int hz, double noise, double delay) {
    RealisticDriverProfile p;
    p.device = device;
    p.control_hz = hz;
    p.stick_noise = noise;
    p.reaction_delay_s = delay;
    return p;
  };
  using D = DriveDevice;
  return {
      {"gamepad, no noise, no delay, 15 Hz", profile(D::Gamepad, 15, 0.0, 0.0)},
      {"gamepad, noise 0.1, no delay, 15 Hz", profile(D::Gamepad, 15, 0.1, 0.0)},
      {"gamepad, noise 0.1, delay 0.2 s, 15 Hz", profile(D::Gamepad, 15, 0.1, 0.2)},
      {"gamepad, noise 0.2, delay 0.3 s, 15 Hz", profile(D::Gamepad, 15, 0.2, 0.3)},
      {"mouse joystick, noise 0.1, delay 0.2 s, 15 Hz", profile(D::MouseJoystick, 15, 0.1, 0.2)},
      {"keyboard, no noise, no delay, 15 Hz", profile(D::Keyboard, 15, 0.0, 0.0)},
      {"keyboard, noise 0.1, delay 0.2 s, 15 Hz", profile(D::Keyboard, 15, 0.1, 0.2)},
      {"gamepad, noise 0.1, delay 0.2 s, 5 Hz", profile(D::Gamepad, 5, 0.1, 0.2)},
  };
}

std::vector<DriveCondition> path_following_conditions() {
  std::vector<DriveCondition> out;
  for (DriveCondition c : standard_drive_conditions()) {
    if (c.profile.stick_noise == 0.0 && c.profile.device != DriveDevice::Keyboard) continue;  // nothing to correct
    c.name += ", follows the path";
    c.profile.follows_path = true;
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<DriveCondition> standing_start_conditions() {
  RealisticDriverProfile delayed;
  delayed.stick_noise = 0.0;
  delayed.reaction_delay_s = 0.2;
  RealisticDriverProfile waiting;
  waiting.stick_noise = 0.1;
  waiting.reaction_delay_s = 0.2;
  waiting.start_wait_s = 1.0;
  RealisticDriverProfile following = waiting;
  following.follows_path = true;
  RealisticDriverProfile both_ends = waiting;
  both_ends.end_wait_s = 5.0;
  return {{"gamepad, no noise, delay 0.2 s, 15 Hz", delayed},
          {"gamepad, noise 0.1, delay 0.2 s, waits 1 s first, 15 Hz", waiting},
          {"gamepad, noise 0.1, delay 0.2 s, waits 1 s first, 15 Hz, follows the path", following},
          {"gamepad, noise 0.1, delay 0.2 s, waits 1 s first and stands 5 s at the end, 15 Hz", both_ends}};
}

std::vector<DriveCondition> keeps_trying_conditions() {
  RealisticDriverProfile trying;
  trying.stick_noise = 0.1;
  trying.reaction_delay_s = 0.2;
  trying.keeps_trying_until_s = 15.0;
  return {{"gamepad, noise 0.1, delay 0.2 s, keeps trying until 15 s, 15 Hz", trying}};
}

std::vector<DriveCondition> gentle_steering_key_conditions() {
  std::vector<DriveCondition> out;
  for (DriveCondition c : standard_drive_conditions()) {
    if (c.profile.device != DriveDevice::Keyboard) continue;
    c.name.replace(0, std::string("keyboard").size(), "keyboard with Shift");
    c.profile.shift_for_gentle_steering = true;
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<AgreementRow> measure_drive_agreement(const SkillExtractor& extractor,
                                                  const std::vector<ParkingTrial>& expert_drives,
                                                  const std::vector<DriveCondition>& conditions, std::uint64_t seed) {
  std::vector<StepSequence> clean;
  for (const ParkingTrial& t : expert_drives) clean.push_back(parking_step_sequence(t));
  const std::vector<Segmentation> clean_skills = extractor.extract_all(clean);
  std::vector<AgreementRow> rows;
  const Rng root(seed);
  for (std::size_t c = 0; c < conditions.size(); ++c) {
    const DriveCondition& condition = conditions[c];
    const Rng per_condition = root.fork(c);
    std::vector<StepSequence> driven;
    AgreementRow row{condition.name, static_cast<int>(expert_drives.size()), {}, {}, 0};
    for (std::size_t i = 0; i < expert_drives.size(); ++i) {
      Rng rng = per_condition.fork(i);
      const ParkingTrial drive = realistic_drive(expert_drives[i], condition.profile, rng);
      row.successes += drive.success.value_or(false);
      driven.push_back(parking_step_sequence(drive));
    }
    const std::vector<Segmentation> driven_skills = extractor.extract_all(driven);
    const int shift = static_cast<int>(
        std::lround((condition.profile.reaction_delay_s + condition.profile.start_wait_s) * parking::kControlHz));
    for (std::size_t i = 0; i < driven.size(); ++i) {
      const StepAgreement a =
          step_agreement(clean_skills[i], clean[i].length(), driven_skills[i], driven[i].length(), shift);
      row.agreement.steps += a.steps;
      row.agreement.agreed += a.agreed;
      const SkillPresence p = skill_presence(clean_skills[i], driven_skills[i]);
      row.presence.skills += p.skills;
      row.presence.present += p.present;
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

StepAgreement keyed_action_agreement(const SkillExtractor& extractor, const std::vector<ParkingTrial>& expert_drives) {
  std::vector<StepSequence> clean, keyed;
  for (const ParkingTrial& t : expert_drives) {
    clean.push_back(parking_step_sequence(t));
    keyed.push_back(with_keyboard_keys(clean.back()));
  }
  const std::vector<Segmentation> a = extractor.extract_all(clean), b = extractor.extract_all(keyed);
  StepAgreement out;
  for (std::size_t i = 0; i < clean.size(); ++i) {
    const StepAgreement d = step_agreement(a[i], clean[i].length(), b[i], keyed[i].length(), 0);
    out.steps += d.steps;
    out.agreed += d.agreed;
  }
  return out;
}

}  // namespace sc
