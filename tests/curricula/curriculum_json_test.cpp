#include "teaching/curricula/curriculum_json.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

Segmentation segmentation_of(const std::vector<std::pair<int, int>>& parts) { return test::segments_of(parts); }

TEST(CurriculumJson, RoundTripsEveryCondition) {
  CurriculumInputs in;
  for (int i = 0; i < 6; ++i) {
    in.expert_skills.push_back(segmentation_of({{i % 3, 4 + i}, {3, 5}, {4, 2 + i}}));
    const int t = 11 + 2 * i;
    in.expert_time_slices.push_back(Segmentation{{{0, 0, t / 3}, {1, t / 3, 2 * t / 3}, {2, 2 * t / 3, t}}});
  }
  in.pretest = estimate_expertise({{0, in.expert_skills[0], segmentation_of({{3, 5}}), -0.4}}, 5, 7);
  for (StudyCondition c : kAllStudyConditions) {
    const Curriculum cur = make_curriculum(c, in, CurriculumConfig::parking());
    const Json doc = curriculum_to_json(cur);
    EXPECT_EQ(doc["condition"], std::string(condition_key(c)));
    EXPECT_EQ(doc["total_steps"], cur.total_steps());
    const Curriculum back = curriculum_from_json(JsonView(parse_json_text(doc.dump(), "c.json"), "c.json"));
    EXPECT_EQ(back.condition, cur.condition);
    EXPECT_EQ(back.budget_steps, cur.budget_steps);
    EXPECT_EQ(back.items, cur.items) << condition_name(c);
  }
}

TEST(CurriculumJson, BadFieldsNameThePath) {
  Json doc = {
      {"condition", "ind-drills"},
      {"budget_steps", 10},
      {"items", Json::array({{{"kind", "lecture"}, {"target_skills", {1}}, {"sessions", 1}, {"material", {}}}})}};
  try {
    curriculum_from_json(JsonView(doc, "c.json"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c.json: $.items[0].kind"), std::string::npos) << e.what();
  }
  doc["condition"] = "cramming";
  EXPECT_THROW(curriculum_from_json(JsonView(doc, "c.json")), InputError);
}

}  // namespace
}  // namespace sc
