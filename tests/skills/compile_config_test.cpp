#include "teaching/skills/compile_config.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"

namespace sc {
namespace {

TEST(CompileConfig, TaskDefaultsFollowThePaper) {
  const CompileConfig p = CompileConfig::defaults_for("parking");
  EXPECT_EQ(p.latent_size, 16);
  EXPECT_EQ(p.num_segments, 4);
  EXPECT_DOUBLE_EQ(p.prior_rate, 10.0);
  EXPECT_DOUBLE_EQ(p.beta_s, 1.0);
  EXPECT_EQ(p.mode, CompileMode::StateDiffAction);
  EXPECT_DOUBLE_EQ(p.learning_rate, 1e-3);
  EXPECT_EQ(p.batch_size, 100);
  const CompileConfig w = CompileConfig::defaults_for("writing");
  EXPECT_EQ(w.latent_size, 24);
  EXPECT_EQ(w.num_segments, 8);
  EXPECT_EQ(w.mode, CompileMode::Action);
  EXPECT_DOUBLE_EQ(w.learning_rate, 1e-3);  // the paper: 5e-3 (too high on our resampled words)
  EXPECT_GT(w.warm_start_iterations, 0);
  EXPECT_EQ(w.batch_size, 50);
  EXPECT_GT(w.resample_step, 0.0);
  EXPECT_THROW(CompileConfig::defaults_for("juggling"), InputError);
}

TEST(CompileConfig, JsonRoundTripAndPathAwareErrors) {
  CompileConfig c = CompileConfig::parking_defaults();
  c.seed = 42;
  c.resample_step = 2.5;
  c.warm_start_iterations = 30;
  c.warm_start_learning_rate = 2e-3;
  c.straight_through_latents = true;
  c.warm_start_units = true;
  c.warm_start_unit_weight = 10.0;
  const Json j = to_json(c);
  const CompileConfig back = compile_config_from_json(JsonView(j, "m.json"));
  EXPECT_EQ(to_json(back), j);
  Json bad = j;
  bad["mode"] = "telepathy";
  try {
    compile_config_from_json(JsonView(bad, "m.json"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("m.json: $.mode"), std::string::npos) << e.what();
  }
  CompileConfig invalid = c;
  invalid.num_segments = 0;
  EXPECT_THROW(invalid.validate("cfg"), InputError);
  invalid = c;
  invalid.warm_start_iterations = -1;
  EXPECT_THROW(invalid.validate("cfg"), InputError);
}

TEST(CompileConfig, ModelsFromBeforeTheWarmStartReadAsTrainedWithoutOne) {
  Json j = to_json(CompileConfig::writing_defaults());
  j.erase("warm_start_iterations");
  j.erase("warm_start_learning_rate");
  const CompileConfig back = compile_config_from_json(JsonView(j, "old.json"));
  EXPECT_EQ(back.warm_start_iterations, 0);
  EXPECT_EQ(back.warm_start_learning_rate, 0.0);
}

TEST(CompileConfig, ModelsFromBeforeStraightThroughLatentsReadAsRelaxed) {
  CompileConfig c = CompileConfig::writing_defaults();
  c.straight_through_latents = true;
  Json j = to_json(c);
  j.erase("straight_through_latents");
  EXPECT_FALSE(compile_config_from_json(JsonView(j, "old.json")).straight_through_latents);
}

TEST(CompileConfig, ModelsFromBeforeWarmStartUnitsReadAsWithout) {
  CompileConfig c = CompileConfig::writing_defaults();
  c.warm_start_units = true;
  Json j = to_json(c);
  j.erase("warm_start_units");
  j.erase("warm_start_unit_weight");
  EXPECT_FALSE(compile_config_from_json(JsonView(j, "old.json")).warm_start_units);
  EXPECT_EQ(compile_config_from_json(JsonView(j, "old.json")).warm_start_unit_weight, 1.0);
}

TEST(CompileConfig, EncoderReadsActionsIsWrittenOnlyWhenOffSoOlderModelsSaveAsBefore) {
  CompileConfig c = CompileConfig::parking_defaults();
  EXPECT_TRUE(c.encoder_reads_actions);
  EXPECT_FALSE(to_json(c).contains("encoder_reads_actions"));
  EXPECT_EQ(to_json(c, /*every_field=*/true).at("encoder_reads_actions"), true);
  c.encoder_reads_actions = false;
  const Json j = to_json(c);
  EXPECT_EQ(j.at("encoder_reads_actions"), false);
  EXPECT_FALSE(compile_config_from_json(JsonView(j, "m.json")).encoder_reads_actions);
  c.validate("cfg");
  CompileConfig actions_only = CompileConfig::writing_defaults();  // action mode: nothing else to read
  actions_only.encoder_reads_actions = false;
  EXPECT_THROW(actions_only.validate("cfg"), InputError);
}

}  // namespace
}  // namespace sc
