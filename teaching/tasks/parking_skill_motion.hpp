#pragma once
// What a parking skill does, measured on the expert segments that carry it, and the plain words for it
// ("reversing while steering left"). Steering > 0 turns the car clockwise on the y-down lot, i.e. to the
// driver's right (engine/parking_view/car_painter.hpp).
#include <string>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

struct ParkingSkillMotion {
  int steps = 0;                  // expert control steps carrying the skill (0: never used)
  double mean_speed = 0.0;        // m/s along the heading, < 0 when reversing
  double mean_acceleration = 0.0; // u0 in [-1, 1]
  double mean_steering = 0.0;     // u1 in [-1, 1], > 0 = right
  double reverse_fraction = 0.0;  // share of the steps whose speed is negative
};

// Step-weighted means over every segment of each skill id in [0, num_skills).
std::vector<ParkingSkillMotion> parking_skill_motions(const std::vector<StepSequence>& experts,
                                                      const std::vector<Segmentation>& segmentations,
                                                      int num_skills);

// "reversing while steering left, braking", "driving forward straight", "unused skill" ...
std::string describe_parking_motion(const ParkingSkillMotion& motion);
// The words of every skill, distinct among used skills: skills that share words get their pace added
// ("reversing straight, slowly" / "..., quickly"; "..., pace 2 of 3" for three or more), so a learner never
// sees two different skills under one name.
std::vector<std::string> describe_parking_motions(const std::vector<ParkingSkillMotion>& motions);

}  // namespace sc
