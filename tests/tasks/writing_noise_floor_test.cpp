#include "teaching/tasks/writing_noise_floor.hpp"

#include <gtest/gtest.h>

#include "engine/core/asset_paths.hpp"
#include "engine/core/error.hpp"
#include "teaching/skills/compile_model.hpp"
#include "teaching/tasks/task_kit_factory.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

NoiseFloorCalibration three_scores() {
  NoiseFloorCalibration c;
  c.learners = 2;
  c.scores = {-0.9, -0.2, 0.0};
  c.skill_twice = {-0.4, -0.1};
  c.skill_more = {-0.3, -0.2, -0.1};
  return c;
}

TEST(WritingNoiseFloorRecord, TheFloorIsRecordedBesideTheSidecarsOtherFields) {
  const std::filesystem::path dir = test::fresh_scratch_dir("writing_noise_floor");
  const std::filesystem::path model = dir / "m.pt";
  EXPECT_FALSE(recorded_noise_floor(model).has_value());  // no sidecar: no floor
  write_json_file(model_sidecar_path(model), Json{{"format", "skillcoach-compile"}, {"data", "words"}});
  EXPECT_FALSE(recorded_noise_floor(model).has_value());  // a sidecar without one: none either
  const NoiseFloorCalibration c = three_scores();
  record_noise_floor(model, c, 7);
  ASSERT_TRUE(recorded_noise_floor(model).has_value());
  EXPECT_DOUBLE_EQ(recorded_noise_floor(model)->segment, c.floor());
  EXPECT_DOUBLE_EQ(recorded_noise_floor(model)->repeated_twice.value(), *c.noise_floor().repeated_twice);
  EXPECT_DOUBLE_EQ(recorded_noise_floor(model)->repeated_more.value(), *c.noise_floor().repeated_more);
  EXPECT_NEAR(*c.noise_floor().repeated_more, -0.3 + 0.02 * 0.1, 1e-12);  // 1 % of 2 gaps: 0.02 of the first
  Json doc = read_json_file(model_sidecar_path(model));
  EXPECT_EQ(doc["data"], "words");  // kept
  EXPECT_EQ(doc["execution_noise_floor"]["seed"], 7);
  EXPECT_EQ(doc["execution_noise_floor"]["learners"], 2);
  EXPECT_EQ(doc["execution_noise_floor"]["skills_more"], 3);
  // A record from before the repeated floors: the segment floor alone, so no repeated evidence is charged.
  doc["execution_noise_floor"].erase("repeated_twice");
  doc["execution_noise_floor"].erase("repeated_more");
  write_json_file(model_sidecar_path(model), doc);
  ASSERT_TRUE(recorded_noise_floor(model).has_value());
  EXPECT_FALSE(recorded_noise_floor(model)->repeated_twice.has_value());
  EXPECT_FALSE(recorded_noise_floor(model)->repeated_more.has_value());
  doc["execution_noise_floor"]["repeated_more"] = "high";
  write_json_file(model_sidecar_path(model), doc);
  EXPECT_THROW((void)recorded_noise_floor(model), InputError);
  doc["execution_noise_floor"]["repeated_more"] = 0.2;  // scores are <= 0: a positive floor is a broken record
  write_json_file(model_sidecar_path(model), doc);
  try {
    (void)recorded_noise_floor(model);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("repeated_more must be <= 0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(model_sidecar_path(model).string()), std::string::npos) << e.what();
  }
}

TEST(WritingNoiseFloorRecord, AFloorThatIsNotANumberNamesTheSidecar) {
  const std::filesystem::path dir = test::fresh_scratch_dir("writing_noise_floor_bad");
  const std::filesystem::path model = dir / "m.pt";
  write_json_file(model_sidecar_path(model), Json{{"execution_noise_floor", {{"value", "low"}}}});
  try {
    (void)recorded_noise_floor(model);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(model_sidecar_path(model).string()), std::string::npos) << e.what();
  }
  EXPECT_THROW(record_noise_floor(dir / "none.pt", three_scores(), 0), InputError);  // no sidecar to add to
}

TEST(WritingNoiseFloorRecord, TheKitTakesTheShippedModelsRecordedFloor) {
  const std::filesystem::path shipped = asset_dir() / "models" / "writing.pt";
  ASSERT_TRUE(recorded_noise_floor(shipped).has_value());
  const auto kit = make_task_kit(TaskKind::writing);
  ASSERT_TRUE(kit->execution_noise_floor().has_value());
  EXPECT_DOUBLE_EQ(kit->execution_noise_floor()->segment, recorded_noise_floor(shipped)->segment);
}

TEST(WritingNoiseFloorRecord, AUsersModelWithABadFloorIsRefusedNamingItsSidecar) {
  const std::filesystem::path dir = test::fresh_scratch_dir("writing_noise_floor_kit");
  const std::filesystem::path model = dir / "mine.pt";
  std::filesystem::copy_file(asset_dir() / "models" / "writing.pt", model);
  write_json_file(model_sidecar_path(model), Json{{"execution_noise_floor", {{"value", nullptr}}}});
  try {
    (void)make_task_kit(TaskKind::writing, model);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mine.pt.json"), std::string::npos) << e.what();
  }
  std::filesystem::remove(model_sidecar_path(model));  // no sidecar at all: the model, without a floor
  EXPECT_FALSE(make_task_kit(TaskKind::writing, model)->execution_noise_floor().has_value());
}

}  // namespace
}  // namespace sc
