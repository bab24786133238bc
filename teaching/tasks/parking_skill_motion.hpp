#pragma once
// What a parking skill does, measured on the expert segments that carry it, and the plain words for it
// ("reversing while steering left"). Steering > 0 turns the car clockwise on the y-down lot, i.e. to the
// driver's right (engine/parking_view/car_painter.hpp).
#include <string>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

struct ParkingSkillMotion {
  int steps = 0;                   // expert control steps carrying the skill (0: never used)
  double mean_speed = 0.0;         // m/s along the heading, < 0 when reversing
  double mean_acceleration = 0.0;  // u0 in [-1, 1]
  double mean_steering = 0.0;      // u1 in [-1, 1], > 0 = right
  double reverse_fraction = 0.0;   // share of the steps whose speed is negative
  double sharp_fraction = 0.0;     // share of the steps steering more than half lock (|u1| > 0.5)
  double braking_fraction = 0.0;   // share of the steps braking: |u0| >= 0.15 against the motion while moving
  double mean_abs_steering = 0.0;  // |u1|: how sharply the skill turns
  double mean_progress = 0.0;      // step / drive length in [0, 1): which part of the manoeuvre it belongs to
};

// Step-weighted means over every segment of each skill id in [0, num_skills).
std::vector<ParkingSkillMotion> parking_skill_motions(const std::vector<StepSequence>& experts,
                                                      const std::vector<Segmentation>& segmentations, int num_skills);

// What the words say (the rules describe_parking_motion uses): the skill reverses ("reversing", "starting to
// reverse": mean speed <= -0.5 m/s, or nearly stopped with mean u0 < 0) / brakes (mean u0 against the
// motion, |mean u0| >= 0.15, while moving).
bool motion_reverses(const ParkingSkillMotion& motion);
// Stops and changes direction: moving each way on at least a quarter of its steps, the pedal against its mean
// motion ("stopping from driving forward, then reversing"; it reverses and it brakes).
bool motion_turns_around(const ParkingSkillMotion& motion);
bool motion_brakes(const ParkingSkillMotion& motion);

// "reversing while steering left, braking", "driving forward straight", "reversing while steering hard left and
// right" (near-zero mean steering, beyond half lock on most steps), "stopping from driving forward, then
// reversing while steering right" (motion_turns_around), "unused skill" ...
std::string describe_parking_motion(const ParkingSkillMotion& motion);
// The words of every skill, distinct among used skills, so a learner never sees two different skills under
// one name. Skills that share words get what sets them apart, in words a learner can act on: their speed
// ("slowly" / "quickly"), how sharply they turn ("with a gentle turn" / "with a sharp turn") or which part
// of the manoeuvre they belong to ("early in the manoeuvre" / "late in the manoeuvre", "at the start /
// midway through / at the end of the manoeuvre") - whichever of the three differs most within the group
// (speeds compared over 8 m/s, steering over full lock, progress over the whole drive). Two to four skills
// get graded words; a larger group is first split by the part of the manoeuvre (thirds).
std::vector<std::string> describe_parking_motions(const std::vector<ParkingSkillMotion>& motions);

}  // namespace sc
