#include "teaching/tasks/parking_skill_motion.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {
// Thresholds for the words, chosen on the expert pool: the planner's speeds are 2-8 m/s while moving,
// its steering saturates at |u1| = 1 in turns and stays below ~0.1 on straight runs.
constexpr double kMovingSpeed = 0.5;    // m/s: slower counts as "nearly stopped"
constexpr double kTurningSteer = 0.15;  // |mean u1| below this is "straight"
constexpr double kBraking = 0.15;       // |mean u0| against the motion above this is "braking"
constexpr double kSharpSteer = 0.5;     // |u1| above this is more than half lock
// A skill whose mean steering is near zero but which steers beyond half lock on most of its steps turns
// hard both ways (e.g. a reversing correction), so "straight" would tell the learner the opposite.
constexpr double kMostSteps = 0.5;
// A skill moving each way on at least this share of its steps, with the pedal against its mean motion,
// stops and turns around (the planner's direction changes): "driving forward, braking" would hide that half
// of it reverses.
constexpr double kBothWays = 0.25;
}  // namespace

std::vector<ParkingSkillMotion> parking_skill_motions(const std::vector<StepSequence>& experts,
                                                      const std::vector<Segmentation>& segmentations, int num_skills) {
  std::vector<ParkingSkillMotion> out(static_cast<std::size_t>(std::max(num_skills, 0)));
  for (std::size_t e = 0; e < experts.size() && e < segmentations.size(); ++e) {
    const StepSequence& x = experts[e];
    const double length = std::max(x.length(), 1);
    for (const SkillSegment& seg : segmentations[e].segments) {
      if (seg.skill < 0 || seg.skill >= num_skills) continue;
      ParkingSkillMotion& m = out[static_cast<std::size_t>(seg.skill)];
      for (int t = seg.begin; t < seg.end && t < x.length(); ++t) {
        ParkingObservation o{};
        for (int k = 0; k < kParkingStateDim; ++k) o[k] = x.states[static_cast<std::size_t>(t * kParkingStateDim + k)];
        const double speed = vehicle_from_observation(o).speed;
        m.mean_speed += speed;
        m.reverse_fraction += speed < 0.0 ? 1.0 : 0.0;
        const double u0 = x.actions[static_cast<std::size_t>(2 * t)];
        const double u1 = x.actions[static_cast<std::size_t>(2 * t + 1)];
        m.mean_acceleration += u0;
        m.mean_steering += u1;
        m.sharp_fraction += std::abs(u1) > kSharpSteer ? 1.0 : 0.0;
        m.mean_abs_steering += std::abs(u1);
        m.mean_progress += t / length;
        m.braking_fraction +=
            std::abs(speed) >= kMovingSpeed && u0 * speed < 0.0 && std::abs(u0) >= kBraking ? 1.0 : 0.0;
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
    m.sharp_fraction /= n;
    m.braking_fraction /= n;
    m.mean_abs_steering /= n;
    m.mean_progress /= n;
  }
  return out;
}

bool motion_turns_around(const ParkingSkillMotion& m) {
  return m.steps > 0 && std::abs(m.mean_speed) >= kMovingSpeed && m.mean_acceleration * m.mean_speed < 0.0 &&
         m.reverse_fraction >= kBothWays && m.reverse_fraction <= 1.0 - kBothWays;
}

bool motion_reverses(const ParkingSkillMotion& m) {
  return m.steps > 0 && (m.mean_speed <= -kMovingSpeed || (m.mean_speed < kMovingSpeed && m.mean_acceleration < 0.0) ||
                         motion_turns_around(m));
}

bool motion_brakes(const ParkingSkillMotion& m) {
  const bool moving = std::abs(m.mean_speed) >= kMovingSpeed;
  return m.steps > 0 && moving && m.mean_acceleration * m.mean_speed < 0.0 && std::abs(m.mean_acceleration) >= kBraking;
}

std::string describe_parking_motion(const ParkingSkillMotion& m) {
  if (m.steps == 0) return "unused skill";
  std::string words;
  const bool turns_around = motion_turns_around(m);
  if (turns_around)
    words = m.mean_acceleration < 0.0 ? "stopping from driving forward, then reversing"
                                      : "stopping from reversing, then driving forward";
  else if (m.mean_speed <= -kMovingSpeed)
    words = "reversing";
  else if (m.mean_speed >= kMovingSpeed)
    words = "driving forward";
  else
    words = m.mean_acceleration < 0.0 ? "starting to reverse" : "starting forward";
  if (m.mean_steering >= kTurningSteer)
    words += " while steering right";
  else if (m.mean_steering <= -kTurningSteer)
    words += " while steering left";
  else if (m.sharp_fraction > kMostSteps)
    words += " while steering hard left and right";
  else
    words += " straight";
  // Acceleration against the direction of motion slows the car down.
  if (motion_brakes(m) && !turns_around) words += ", braking";
  return words;
}

namespace {

// What can set apart skills that share words: a value per skill, its scale and graded words (low to high).
struct Attribute {
  double (*value)(const ParkingSkillMotion&);
  double scale;
  std::vector<std::vector<std::string>> words;  // words[n - 2]: for a group of n
};

const std::vector<Attribute>& attributes() {
  static const std::vector<Attribute> list = {
      {[](const ParkingSkillMotion& m) { return std::abs(m.mean_speed); },
       8.0,
       {{"slowly", "quickly"},
        {"slowly", "at medium speed", "quickly"},
        {"very slowly", "slowly", "quickly", "very quickly"}}},
      {[](const ParkingSkillMotion& m) { return m.mean_abs_steering; },
       1.0,
       {{"with a gentle turn", "with a sharp turn"},
        {"with a gentle turn", "with a medium turn", "with a sharp turn"},
        {"with a very gentle turn", "with a gentle turn", "with a sharp turn", "with a very sharp turn"}}},
      {[](const ParkingSkillMotion& m) { return m.mean_progress; },
       1.0,
       {{"early in the manoeuvre", "late in the manoeuvre"},
        {"at the start of the manoeuvre", "midway through the manoeuvre", "at the end of the manoeuvre"},
        {"at the very start of the manoeuvre", "early in the manoeuvre", "late in the manoeuvre",
         "at the very end of the manoeuvre"}}},
  };
  return list;
}

// The smallest gap between the group's sorted values, over the attribute's scale.
double separation(const Attribute& a, const std::vector<ParkingSkillMotion>& motions, std::vector<std::size_t> group) {
  std::sort(group.begin(), group.end(),
            [&](std::size_t x, std::size_t y) { return a.value(motions[x]) < a.value(motions[y]); });
  double gap = 1e300;
  for (std::size_t k = 1; k < group.size(); ++k)
    gap = std::min(gap, (a.value(motions[group[k]]) - a.value(motions[group[k - 1]])) / a.scale);
  return gap;
}

// Appends to words[i] of each skill in `group` (2..4 skills) the graded words of the attribute among
// `candidates` (indices into attributes()) that sets them apart most.
void grade(std::vector<std::string>& words, const std::vector<ParkingSkillMotion>& motions,
           std::vector<std::size_t> group, const std::vector<std::size_t>& candidates = {0, 1, 2}) {
  const auto& list = attributes();
  std::size_t best = candidates.front();
  for (std::size_t a : candidates)
    if (separation(list[a], motions, group) > separation(list[best], motions, group)) best = a;
  const Attribute& a = list[best];
  std::stable_sort(group.begin(), group.end(),
                   [&](std::size_t x, std::size_t y) { return a.value(motions[x]) < a.value(motions[y]); });
  for (std::size_t k = 0; k < group.size(); ++k) words[group[k]] += ", " + a.words[group.size() - 2][k];
}

// More than four skills sharing words in one part of the manoeuvre (a model of one's own can have them): the
// slower and the faster half, each told apart by how sharply it turns. Numbered only beyond eight.
void split_by_speed_then_turn(std::vector<std::string>& words, const std::vector<ParkingSkillMotion>& motions,
                              std::vector<std::size_t> members) {
  const Attribute& speed = attributes()[0];
  std::stable_sort(members.begin(), members.end(),
                   [&](std::size_t x, std::size_t y) { return speed.value(motions[x]) < speed.value(motions[y]); });
  const auto middle = members.begin() + static_cast<std::ptrdiff_t>(members.size() / 2);
  const std::vector<std::size_t> halves[2] = {{members.begin(), middle}, {middle, members.end()}};
  for (int h = 0; h < 2; ++h) {
    for (std::size_t i : halves[h]) words[i] += h == 0 ? ", slowly" : ", quickly";
    if (halves[h].size() > 4) {
      for (std::size_t k = 0; k < halves[h].size(); ++k) words[halves[h][k]] += " (" + std::to_string(k + 1) + ")";
    } else if (halves[h].size() >= 2) {
      grade(words, motions, halves[h], {1});
    }
  }
}

void tell_apart(std::vector<std::string>& words, const std::vector<ParkingSkillMotion>& motions,
                const std::vector<std::size_t>& group) {
  if (group.size() < 2) return;
  if (group.size() <= 4) {
    grade(words, motions, group);
    return;
  }
  // Too many for graded words: split by thirds of the manoeuvre first, then grade within each third.
  const std::vector<std::string> thirds = attributes()[2].words[1];
  std::map<int, std::vector<std::size_t>> by_third;
  for (std::size_t i : group) by_third[std::min(2, static_cast<int>(3.0 * motions[i].mean_progress))].push_back(i);
  for (auto& [third, members] : by_third) {
    for (std::size_t i : members) words[i] += ", " + thirds[static_cast<std::size_t>(third)];
    if (members.size() <= 4)
      tell_apart(words, motions, members);
    else
      split_by_speed_then_turn(words, motions, members);
  }
}

}  // namespace

std::vector<std::string> describe_parking_motions(const std::vector<ParkingSkillMotion>& motions) {
  std::vector<std::string> words;
  std::map<std::string, std::vector<std::size_t>> groups;  // shared words -> used skills
  for (std::size_t i = 0; i < motions.size(); ++i) {
    words.push_back(describe_parking_motion(motions[i]));
    if (motions[i].steps > 0) groups[words.back()].push_back(i);
  }
  for (const auto& [text, group] : groups) tell_apart(words, motions, group);
  return words;
}

}  // namespace sc
