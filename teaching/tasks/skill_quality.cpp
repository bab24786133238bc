#include "teaching/tasks/skill_quality.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "engine/core/error.hpp"
#include "engine/core/task_kind.hpp"
#include "teaching/skills/skill_usage.hpp"
#include "teaching/tasks/parking_steps.hpp"
#include "teaching/tasks/writing_skill_places.hpp"

namespace sc {

BoundaryScore writing_boundary_score(const std::vector<Segmentation>& predicted, const std::vector<SkillDemo>& demos,
                                     double tolerance_fraction) {
  BoundaryScore total;
  for (std::size_t i = 0; i < demos.size() && i < predicted.size(); ++i) {
    if (demos[i].true_boundaries.empty()) continue;
    const int tolerance = static_cast<int>(std::lround(tolerance_fraction * demos[i].steps.length()));
    total += score_boundaries(interior_boundaries(predicted[i]), demos[i].true_boundaries, tolerance);
  }
  return total;
}

namespace {

// Signed speed (m/s) of an observation: velocity (x5, normalised by 5 m/s) projected on the heading.
double signed_speed(const StepSequence& s, int t) {
  const float* o = &s.states[static_cast<std::size_t>(t * s.state_dim)];
  return 5.0 * (o[2] * o[4] + o[3] * o[5]);
}

}  // namespace

ParkingStepKind classify_parking_step(const StepSequence& s, int t) {
  const int next = t + 1 < s.length() ? t + 1 : t;
  ParkingStepKind kind;
  kind.reversing = signed_speed(s, next) < 0.0;
  const double steer = s.actions[static_cast<std::size_t>(t * s.action_dim + 1)];
  kind.turn = steer > kStraightSteering ? 1 : (steer < -kStraightSteering ? -1 : 0);
  return kind;
}

double ParkingSkillPurity::turn_purity() const { return std::max({left, right, straight}); }

ParkingPurityReport parking_skill_purity(const std::vector<Segmentation>& segmentations,
                                         const std::vector<StepSequence>& trajectories) {
  struct Counts {
    int steps = 0, reversing = 0, left = 0, right = 0;
  };
  std::map<int, Counts> counts;
  for (std::size_t i = 0; i < segmentations.size() && i < trajectories.size(); ++i) {
    const StepSequence& s = trajectories[i];
    if (s.state_dim != kParkingStateDim || s.action_dim != kParkingActionDim ||
        s.states.size() != static_cast<std::size_t>(s.length() * s.state_dim))
      throw InputError("parking trajectory " + std::to_string(i), "is not a 12-D state / 2-D action step sequence");
    for (const SkillSegment& seg : segmentations[i].segments)
      for (int t = seg.begin; t < seg.end && t < s.length(); ++t) {
        const ParkingStepKind k = classify_parking_step(s, t);
        Counts& c = counts[seg.skill];
        ++c.steps;
        c.reversing += k.reversing;
        c.left += k.turn > 0;
        c.right += k.turn < 0;
      }
  }
  ParkingPurityReport out;
  int total = 0;
  for (const auto& [skill, c] : counts) {
    const double n = c.steps;
    ParkingSkillPurity p{skill,
                         c.steps,
                         c.reversing / n,
                         (c.steps - c.reversing) / n,
                         c.left / n,
                         c.right / n,
                         (c.steps - c.left - c.right) / n};
    out.direction_purity += p.direction_purity() * n;
    out.turn_purity += p.turn_purity() * n;
    total += c.steps;
    out.skills.push_back(p);
  }
  if (total > 0) {
    out.direction_purity /= total;
    out.turn_purity /= total;
  }
  return out;
}

char WritingSkillSymbols::majority() const {
  char best = '\0';
  int most = -1;
  for (const auto& [symbol, n] : symbol_steps)
    if (n > most) best = symbol, most = n;  // map order: the smaller character wins a tie
  return best;
}

double WritingSkillSymbols::purity() const {
  return steps > 0 ? static_cast<double>(symbol_steps.at(majority())) / steps : 0.0;
}

WritingSymbolReport writing_symbol_purity(const std::vector<Segmentation>& segmentations,
                                          const std::vector<SkillDemo>& demos) {
  // The counting is the kit's (writing_skill_places): each demo is a word whose symbols start at 0 and at
  // its true boundaries.
  std::vector<WordCharacters> words;
  std::vector<Segmentation> segs;
  int num_skills = 0;
  for (std::size_t i = 0; i < demos.size() && i < segmentations.size(); ++i) {
    const SkillDemo& d = demos[i];
    if (d.true_boundaries.empty() || d.label.size() != d.true_boundaries.size() + 1) continue;
    std::vector<int> starts{0};
    starts.insert(starts.end(), d.true_boundaries.begin(), d.true_boundaries.end());
    words.push_back({d.label, std::move(starts), d.steps.length()});
    segs.push_back(segmentations[i]);
    for (const SkillSegment& seg : segmentations[i].segments) num_skills = std::max(num_skills, seg.skill + 1);
  }
  const std::vector<WritingSkillPlace> places = writing_skill_places(words, segs, num_skills);
  WritingSymbolReport out;
  std::map<char, int> most;  // symbol -> steps of its skill in symbol_skill
  long total = 0;
  for (int m = 0; m < num_skills; ++m) {
    const WritingSkillPlace& place = places[static_cast<std::size_t>(m)];
    if (place.steps == 0) continue;
    const WritingSkillSymbols s{m, place.steps, place.character_steps};
    out.purity += s.purity() * s.steps;
    total += s.steps;
    out.skills.push_back(s);
    for (const auto& [symbol, n] : place.character_steps)
      if (n > most[symbol]) most[symbol] = n, out.symbol_skill[symbol] = m;  // ids ascend: the smaller wins a tie
  }
  if (total > 0) out.purity /= static_cast<double>(total);
  return out;
}

Json to_json(const WritingSymbolReport& r) {
  Json per_skill = Json::array();
  for (const WritingSkillSymbols& s : r.skills) {
    Json symbols = Json::object();
    for (const auto& [symbol, n] : s.symbol_steps) symbols[std::string(1, symbol)] = n;
    per_skill.push_back({{"skill", s.skill},
                         {"steps", s.steps},
                         {"majority", std::string(1, s.majority())},
                         {"purity", s.purity()},
                         {"symbol_steps", std::move(symbols)}});
  }
  Json symbol_skill = Json::object();
  for (const auto& [symbol, skill] : r.symbol_skill) symbol_skill[std::string(1, symbol)] = skill;
  return Json{{"purity", r.purity}, {"symbol_skill", std::move(symbol_skill)}, {"per_skill", std::move(per_skill)}};
}

Json to_json(const BoundaryScore& s) {
  return Json{{"precision", s.precision()},
              {"recall", s.recall()},
              {"f1", s.f1()},
              {"true_positives", s.true_positives},
              {"false_positives", s.false_positives},
              {"false_negatives", s.false_negatives}};
}

Json to_json(const ParkingPurityReport& r) {
  Json per_skill = Json::array();
  for (const ParkingSkillPurity& p : r.skills)
    per_skill.push_back({{"skill", p.skill},
                         {"steps", p.steps},
                         {"reversing", p.reversing},
                         {"forward", p.forward},
                         {"left", p.left},
                         {"right", p.right},
                         {"straight", p.straight}});
  return Json{
      {"direction_purity", r.direction_purity}, {"turn_purity", r.turn_purity}, {"per_skill", std::move(per_skill)}};
}

Json skill_quality_report(const SkillDataSet& data, const std::vector<Segmentation>& segmentations) {
  if (segmentations.size() != data.demos.size())
    throw InputError("skill quality", "got " + std::to_string(segmentations.size()) + " segmentations for " +
                                          std::to_string(data.demos.size()) + " trajectories");
  long steps = 0;
  bool boundaries_known = false;
  for (const SkillDemo& d : data.demos) {
    steps += d.steps.length();
    boundaries_known = boundaries_known || !d.true_boundaries.empty();
  }
  Json out{{"task", data.task},
           {"data", data.description},
           {"trajectories", data.demos.size()},
           {"steps", steps},
           {"usage", to_json(skill_usage(segmentations))}};
  if (boundaries_known) {
    out["boundaries"] = to_json(writing_boundary_score(segmentations, data.demos));
    out["boundaries"]["tolerance"] = "+-5% of the word's length in steps";
    out["symbols"] = to_json(writing_symbol_purity(segmentations, data.demos));
  }
  if (task_kind_of(data.task) == TaskKind::parking)
    out["purity"] = to_json(parking_skill_purity(segmentations, data.steps()));
  return out;
}

}  // namespace sc
