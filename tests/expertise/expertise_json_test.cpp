#include "teaching/expertise/expertise_json.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

Segmentation segmentation_of(const std::vector<int>& skills) { return test::segments_of(skills, 2); }

TEST(ExpertiseJson, RoundTrips) {
  const ExpertiseEstimate e = estimate_expertise({{3, segmentation_of({0, 1, 2, 1}), segmentation_of({2}), -0.75},
                                                  {5, segmentation_of({2, 3}), segmentation_of({2, 3}), -0.1}},
                                                 5, 2);
  const Json doc = expertise_to_json(e);
  EXPECT_EQ(doc["targets"], Json({0, 1}));  // E_0 = -0.75, E_1 = -0.75/2 - 0.75/4
  EXPECT_EQ(doc["contributions"][1][1]["position"], 4);
  const ExpertiseEstimate back = expertise_from_json(JsonView(parse_json_text(doc.dump(), "diag.json"), "diag.json"));
  EXPECT_EQ(back.expertise, e.expertise);
  EXPECT_EQ(back.occurrences, e.occurrences);
  EXPECT_EQ(back.contributions, e.contributions);
  EXPECT_EQ(back.ranking, e.ranking);
  EXPECT_EQ(back.targets, e.targets);
}

TEST(ExpertiseJson, ExecutionPenaltiesKeepTheirKindAndOlderRecordsReadAsMissing) {
  ExpertiseEstimate e = estimate_expertise({{3, segmentation_of({0, 1}), segmentation_of({0}), -0.5}}, 2, 2);
  e.contributions[0].push_back({0, 3, 1, -0.4, 0.4, true});
  e.contributions[1].push_back({0, 3, 2, -0.1, 0.05, true, true});
  Json doc = expertise_to_json(e);
  const ExpertiseEstimate back = expertise_from_json(JsonView(doc, "diag.json"));
  EXPECT_EQ(back.contributions, e.contributions);
  EXPECT_TRUE(back.contributions[0].back().execution);
  EXPECT_FALSE(back.contributions[0].back().repeated);
  EXPECT_TRUE(back.contributions[1].back().repeated);
  for (Json& per_skill : doc["contributions"])
    for (Json& c : per_skill) c.erase("execution"), c.erase("repeated");  // a record written before the fields
  const ExpertiseEstimate old = expertise_from_json(JsonView(doc, "diag.json"));
  for (const auto& per_skill : old.contributions)
    for (const ExpertiseContribution& c : per_skill) EXPECT_FALSE(c.execution || c.repeated);
}

TEST(ExpertiseJson, TheLearnersHandIsKeptAndWrittenOnlyWhenThereIsOne) {
  ExpertiseEstimate e = estimate_expertise({{3, segmentation_of({0, 1}), segmentation_of({0}), -0.5}}, 2, 2);
  EXPECT_FALSE(expertise_to_json(e).contains("learner_hand"));  // records as before the field existed
  EXPECT_EQ(expertise_from_json(JsonView(expertise_to_json(e), "diag.json")).learner_hand, "");
  e.learner_hand = "the letters of Omniglot drawer 5";
  EXPECT_EQ(expertise_from_json(JsonView(expertise_to_json(e), "diag.json")).learner_hand, e.learner_hand);
  Json doc = expertise_to_json(e);
  doc["learner_hand"] = 5;
  EXPECT_THROW(expertise_from_json(JsonView(doc, "diag.json")), InputError);
}

TEST(ExpertiseJson, BadDocumentsNameThePath) {
  Json doc = expertise_to_json(estimate_expertise({{0, segmentation_of({0, 1}), segmentation_of({}), -1.0}}, 2, 2));
  doc["ranking"][0] = 9;
  try {
    expertise_from_json(JsonView(doc, "diag.json"));
    FAIL() << "no error";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("diag.json: $.ranking[0]"), std::string::npos) << err.what();
  }
  doc = expertise_to_json(estimate_expertise({{0, segmentation_of({0, 1}), segmentation_of({}), -1.0}}, 2, 2));
  doc["occurrences"].push_back(1);
  EXPECT_THROW(expertise_from_json(JsonView(doc, "diag.json")), InputError);
}

}  // namespace
}  // namespace sc
