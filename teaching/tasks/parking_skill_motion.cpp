#include "teaching/tasks/parking_skill_motion.hpp"

#include <algorithm>
#include <cmath>

#include "teaching/tasks/distinct_skill_words.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {
// Thresholds for the words, chosen on the expert pool: the planner's speeds are 2-8 m/s while moving,
// its steering saturates at |u1| = 1 in turns and stays below ~0.1 on straight runs.
constexpr double kMovingSpeed = 0.5;    // m/s: slower counts as "nearly stopped"
constexpr double kTurningSteer = 0.15;  // |mean u1| below this is "straight"
constexpr double kBraking = 0.15;       // |mean u0| against the motion above this is "braking"
}  // namespace

std::vector<ParkingSkillMotion> parking_skill_motions(const std::vector<StepSequence>& experts,
                                                      const std::vector<Segmentation>& segmentations,
                                                      int num_skills) {
  std::vector<ParkingSkillMotion> out(static_cast<std::size_t>(std::max(num_skills, 0)));
  for (std::size_t e = 0; e < experts.size() && e < segmentations.size(); ++e) {
    const StepSequence& x = experts[e];
    for (const SkillSegment& seg : segmentations[e].segments) {
      if (seg.skill < 0 || seg.skill >= num_skills) continue;
      ParkingSkillMotion& m = out[static_cast<std::size_t>(seg.skill)];
      for (int t = seg.begin; t < seg.end && t < x.length(); ++t) {
        ParkingObservation o{};
        for (int k = 0; k < kParkingStateDim; ++k) o[k] = x.states[static_cast<std::size_t>(t * kParkingStateDim + k)];
        const double speed = vehicle_from_observation(o).speed;
        m.mean_speed += speed;
        m.reverse_fraction += speed < 0.0 ? 1.0 : 0.0;
        m.mean_acceleration += x.actions[static_cast<std::size_t>(2 * t)];
        m.mean_steering += x.actions[static_cast<std::size_t>(2 * t + 1)];
        ++m.steps;
      }
    }
  }
  for (ParkingSkillMotion& m : out) {
    if (m.steps == 0) continue;
    const double n = m.steps;
    m.mean_speed /= n;
    m.reverse_fraction /= n;
    m.mean_acceleration /= n;
    m.mean_steering /= n;
  }
  return out;
}

std::string describe_parking_motion(const ParkingSkillMotion& m) {
  if (m.steps == 0) return "unused skill";
  std::string words;
  if (m.mean_speed <= -kMovingSpeed)
    words = "reversing";
  else if (m.mean_speed >= kMovingSpeed)
    words = "driving forward";
  else
    words = m.mean_acceleration < 0.0 ? "starting to reverse" : "starting forward";
  if (m.mean_steering >= kTurningSteer)
    words += " while steering right";
  else if (m.mean_steering <= -kTurningSteer)
    words += " while steering left";
  else
    words += " straight";
  // Acceleration against the direction of motion slows the car down.
  const bool moving = std::abs(m.mean_speed) >= kMovingSpeed;
  if (moving && m.mean_acceleration * m.mean_speed < 0.0 && std::abs(m.mean_acceleration) >= kBraking)
    words += ", braking";
  return words;
}

std::vector<std::string> describe_parking_motions(const std::vector<ParkingSkillMotion>& motions) {
  std::vector<std::string> words;
  std::vector<bool> used;
  for (const auto& m : motions) {
    words.push_back(describe_parking_motion(m));
    used.push_back(m.steps > 0);
  }
  return distinct_skill_words(
      std::move(words), used,
      [&](std::size_t a, std::size_t b) { return std::abs(motions[a].mean_speed) < std::abs(motions[b].mean_speed); },
      [](const std::string& text, std::size_t k, std::size_t n) {
        if (n == 2) return text + (k == 0 ? ", slowly" : ", quickly");
        return text + ", pace " + std::to_string(k + 1) + " of " + std::to_string(n);
      });
}

}  // namespace sc
