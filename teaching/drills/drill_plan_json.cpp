#include "teaching/drills/drill_plan_json.hpp"

#include <climits>
#include <string>

namespace sc {
namespace {

int int_in(const JsonView& v, long long lo, long long hi) {
  const long long x = v.integer();
  if (x < lo || x > hi)
    v.fail("value " + std::to_string(x) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(x);
}

}  // namespace

Json drill_plan_to_json(const DrillPlan& plan) {
  Json segments = Json::array();
  for (const auto& s : plan.segments) {
    segments.push_back({{"skill", s.skill}, {"expert", s.expert}, {"begin", s.begin}, {"end", s.end}});
  }
  return {{"target_skill", plan.target_skill},
          {"ngram", plan.ngram},
          {"ngram_count", plan.ngram_count},
          {"repetitions", plan.repetitions},
          {"segments", std::move(segments)}};
}

DrillPlan drill_plan_from_json(const JsonView& view) {
  DrillPlan plan;
  plan.target_skill = int_in(view.at("target_skill"), -1, INT_MAX);
  const JsonView ngram = view.at("ngram");
  for (std::size_t i = 0; i < ngram.size(); ++i) plan.ngram.push_back(int_in(ngram.at(i), 0, INT_MAX));
  plan.ngram_count = int_in(view.at("ngram_count"), 0, INT_MAX);
  plan.repetitions = int_in(view.at("repetitions"), 1, INT_MAX);
  const JsonView segments = view.at("segments");
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const JsonView s = segments.at(i);
    DrillSegment seg{int_in(s.at("skill"), 0, INT_MAX), int_in(s.at("expert"), 0, INT_MAX),
                     int_in(s.at("begin"), 0, INT_MAX), int_in(s.at("end"), 0, INT_MAX)};
    if (seg.end <= seg.begin) s.fail("empty segment: end must be greater than begin");
    plan.segments.push_back(seg);
  }
  return plan;
}

}  // namespace sc
