#include "teaching/drills/drill_plan_json.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"

namespace sc {
namespace {

TEST(DrillPlanJson, RoundTrips) {
  DrillPlan plan;
  plan.target_skill = 3;
  plan.ngram = {1, 3};
  plan.ngram_count = 12;
  plan.repetitions = 2;
  plan.segments = {{1, 17, 0, 6}, {3, 4, 9, 20}, {1, 17, 0, 6}, {3, 4, 9, 20}};
  const Json doc = drill_plan_to_json(plan);
  EXPECT_EQ(doc["segments"][1]["expert"], 4);
  EXPECT_EQ(drill_plan_from_json(JsonView(parse_json_text(doc.dump(), "d.json"), "d.json")), plan);
}

TEST(DrillPlanJson, RejectsEmptySegmentsAndNegativeIds) {
  Json doc = drill_plan_to_json(DrillPlan{-1, {2}, 1, 1, {{2, 0, 5, 5}}});
  try {
    drill_plan_from_json(JsonView(doc, "d.json"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("$.segments[0]"), std::string::npos) << e.what();
  }
  doc = drill_plan_to_json(DrillPlan{-1, {2}, 1, 1, {{2, -1, 0, 5}}});
  EXPECT_THROW(drill_plan_from_json(JsonView(doc, "d.json")), InputError);
  doc = drill_plan_to_json(DrillPlan{-1, {2}, 1, 0, {{2, 0, 0, 5}}});
  EXPECT_THROW(drill_plan_from_json(JsonView(doc, "d.json")), InputError);
}

}  // namespace
}  // namespace sc
