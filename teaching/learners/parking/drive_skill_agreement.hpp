#pragma once
// Robustness of a parking skill model to how people drive: the skills it gives a realistic driver's copy
// of an expert drive (realistic_driver.hpp) against the skills of the clean drive, step by step.
//
// Spec. Agreement of one drive = the share of the clean drive's control steps t whose skill equals the
// realistic drive's skill at step t + d, d = the driver's reaction delay plus its start wait in control steps
// (rounded): the driver does at t + d what the expert did at t, so a skill model that follows the motion labels both
// alike. Steps past the end of either drive do not count (a drive that collided early counts fewer
// steps). A condition's agreement is step-weighted over its drives.
#include <string>
#include <vector>

#include "teaching/learners/parking/realistic_driver.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

// The skill id at each step 0..length-1 (-1 where no segment covers the step).
std::vector<int> skill_per_step(const Segmentation& segmentation, int length);

struct StepAgreement {
  int steps = 0;   // compared steps
  int agreed = 0;  // of them with the same skill
  double share() const { return steps > 0 ? static_cast<double>(agreed) / steps : 0.0; }
};
StepAgreement step_agreement(const Segmentation& clean, int clean_length, const Segmentation& driven, int driven_length,
                             int shift);

// What Alg. 2 asks of a learner's trial: does each skill of the expert's drive occur anywhere in it? Per
// drive, the clean drive's distinct skills that also occur in the realistic copy's segmentation.
struct SkillPresence {
  int skills = 0;   // distinct skills of the clean drives
  int present = 0;  // of them, also in the copy
  double share() const { return skills > 0 ? static_cast<double>(present) / skills : 0.0; }
};
SkillPresence skill_presence(const Segmentation& clean, const Segmentation& driven);

struct DriveCondition {
  std::string name;  // e.g. "keyboard, noise 0.1, delay 0.2 s, 15 Hz"
  RealisticDriverProfile profile;
};
// The table's rows: 15 Hz input alone, stick noise, delay, each device, a harder novice, 5 Hz input.
std::vector<DriveCondition> standard_drive_conditions();
// The same drivers watching the expert's path and correcting their drift (follows_path), for every standard
// condition but the noiseless gamepad: the motion stays near the expert's, so the rows measure how the model
// reads noisy, delayed and keyed input on the expert's motion rather than a drive that went elsewhere.
std::vector<DriveCondition> path_following_conditions();
// Standing still: the expert's drive a reaction delay late with no noise (the motion is the expert's, only
// later); noisy drivers who stand still for a second first, as a learner does after the countdown, open loop and
// following the path; and one who also stands five seconds at the end, as a learner who gave up on the spot does
// until the time limit. Kept apart from the lists above so that their rows keep their draws.
std::vector<DriveCondition> standing_start_conditions();
// A noisy driver who has not parked when the expert's plan ends and keeps driving towards the expert's end until
// 15 s (the trainer's time limit of a 25-step drive): the drive runs three to four times as long as the expert's.
// Its agreement counts the expert's steps only; its skill presence is what Alg. 2 asks of the whole drive.
std::vector<DriveCondition> keeps_trying_conditions();
// Keyboard drivers who hold Shift to steer at half lock where the expert steers nearer half than full lock or
// straight, without and with noise and delay (the two keyboard rows of the standard conditions otherwise).
std::vector<DriveCondition> gentle_steering_key_conditions();

struct AgreementRow {
  std::string condition;
  int drives = 0;
  StepAgreement agreement;
  SkillPresence presence;
  int successes = 0;  // realistic drives that still parked (how far the noise takes the car off the plan)
};

// Every condition over every expert drive (control-rate trials); the driver of drive i under condition c
// uses Rng(seed).fork(c).fork(i). Deterministic.
std::vector<AgreementRow> measure_drive_agreement(const SkillExtractor& extractor,
                                                  const std::vector<ParkingTrial>& expert_drives,
                                                  const std::vector<DriveCondition>& conditions, std::uint64_t seed);

// Why the keyboard rows disagree: the clean drives segmented again with every action replaced by the keys a
// keyboard would give for it (keyboard_keys) and the states kept, so the car moves exactly as the expert's
// did and only the action values the model reads change. Agreement with the clean drives' skills, step by
// step (no shift), over all drives. A model that followed the motion alone would agree on every step.
StepAgreement keyed_action_agreement(const SkillExtractor& extractor, const std::vector<ParkingTrial>& expert_drives);

}  // namespace sc
