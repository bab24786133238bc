// CompILE model files: round trip, sidecar, and one-line errors for every kind of bad file.
#include "teaching/skills/compile_model.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "engine/core/error.hpp"
#include "teaching/skills/compile_extractor.hpp"
#include "teaching/skills/compile_trainer.hpp"
#include "teaching/skills/model_file.hpp"
#include "teaching/skills/synthetic_sequences.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

std::filesystem::path model_scratch(const std::string& name) { return test::scratch_path("compile_model_test", name); }

std::vector<StepSequence> data() {
  std::vector<StepSequence> out;
  for (const auto& p : constant_primitive_sequences(12, 3, 3, 4, 9, 12, 21)) out.push_back(p.steps);
  return out;
}

// A small statediff+action model (the parking mode), trained for two iterations.
std::filesystem::path trained_model(bool encoder_reads_actions = true, const std::string& name = "model.scm") {
  CompileConfig c = CompileConfig::parking_defaults();
  c.encoder_reads_actions = encoder_reads_actions;
  c.task = "parking";
  c.hidden = 16;
  c.latent_size = 5;
  c.iterations = 2;
  c.batch_size = 6;
  const auto path = model_scratch(name);
  ModelProvenance prov;
  prov.data_description = "12 synthetic sequences";
  prov.git_revision = "abc123";
  CompileTrainer trainer(c);
  CompileModel model = trainer.train(data(), data());
  prov.metrics = trainer.summary().to_json();
  model.save(path, prov);
  return path;
}

void expect_load_error(const std::filesystem::path& p, const std::string& problem, const std::string& task = "",
                       int state_dim = -1, int action_dim = -1) {
  try {
    CompileModel::load(p, task, state_dim, action_dim);
    FAIL() << "no error for " << p << " (" << problem << ")";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(p.string()), std::string::npos) << what;
    EXPECT_NE(what.find(problem), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(CompileModel, RoundTripGivesIdenticalSegmentationAndSidecar) {
  const auto path = trained_model();
  const auto trajectories = data();
  const CompileExtractor loaded = CompileExtractor::load(path, "parking", 12, 2);
  const CompileModel again = CompileModel::load(path);
  const auto segs = loaded.extract_all(trajectories);
  EXPECT_EQ(segs, again.segment(trajectories));
  for (std::size_t i = 0; i < trajectories.size(); ++i) {
    EXPECT_EQ(loaded.extract(trajectories[i]), segs[i]);  // batched == one at a time
    ASSERT_FALSE(segs[i].segments.empty());
    EXPECT_EQ(segs[i].segments.front().begin, 0);
    EXPECT_EQ(segs[i].segments.back().end, trajectories[i].length());
    for (std::size_t k = 1; k < segs[i].segments.size(); ++k)
      EXPECT_EQ(segs[i].segments[k].begin, segs[i].segments[k - 1].end);
    for (const auto& s : segs[i].segments) {
      EXPECT_GT(s.length(), 0);
      EXPECT_LT(s.skill, loaded.num_skills());
    }
  }
  // Saving the loaded model reproduces the file byte for byte.
  again.save(model_scratch("resaved.scm"));
  EXPECT_EQ(test::read_bytes(path), test::read_bytes(model_scratch("resaved.scm")));

  const Json sidecar = read_json_file(model_sidecar_path(path));
  EXPECT_EQ(sidecar.at("format_version"), kModelFormatVersion);
  EXPECT_EQ(sidecar.at("task"), "parking");
  EXPECT_EQ(sidecar.at("git_revision"), "abc123");
  EXPECT_EQ(sidecar.at("data"), "12 synthetic sequences");
  EXPECT_EQ(sidecar.at("config").at("mode"), "statediff+action");
  EXPECT_TRUE(sidecar.at("metrics").contains("best_valid_nll"));

  StepSequence wrong = trajectories[0];
  wrong.state_dim = 3;
  EXPECT_THROW(loaded.extract(wrong), InputError);
}

TEST(CompileModel, ASidecarsFurtherEntriesAreWrittenButNeverOverrideItsOwnFields) {
  const CompileModel model = CompileModel::load(trained_model());
  ModelProvenance prov;
  prov.data_description = "kept";
  prov.extra = Json{{"execution_noise_floor", {{"value", -0.5}}}, {"task", "writing"}, {"data", "stale"}};
  const auto path = model_scratch("extra.scm");
  model.save(path, prov);
  const Json sidecar = read_json_file(model_sidecar_path(path));
  EXPECT_EQ(sidecar.at("execution_noise_floor").at("value"), -0.5);
  EXPECT_EQ(sidecar.at("task"), "parking");
  EXPECT_EQ(sidecar.at("data"), "kept");
}

TEST(CompileModel, AResamplingModelReadsAtItsPhasesAndKeepsTheSettingInItsFile) {
  CompileConfig c = CompileConfig::writing_defaults();  // action mode, resampled, 3 phases
  c.hidden = 16;
  c.latent_size = 5;
  c.iterations = 2;
  c.batch_size = 6;
  c.warm_start_iterations = 0;
  c.restarts = 1;
  c.resample_step = 2.5;
  ASSERT_EQ(c.readout_phases, 3);
  CompileModel model = CompileTrainer(c).train(data(), data());
  const auto trajectories = data();
  const auto voted = model.segment(trajectories);
  for (std::size_t i = 0; i < trajectories.size(); ++i) {
    ASSERT_FALSE(voted[i].segments.empty());
    EXPECT_EQ(voted[i].segments.front().begin, 0);
    EXPECT_EQ(voted[i].segments.back().end, trajectories[i].length());
    for (std::size_t k = 1; k < voted[i].segments.size(); ++k)
      EXPECT_EQ(voted[i].segments[k].begin, voted[i].segments[k - 1].end);
    EXPECT_EQ(model.segment({trajectories[i]})[0], voted[i]);  // batched == one at a time
  }
  const auto path = model_scratch("phases.scm");
  model.save(path);
  EXPECT_EQ(CompileModel::load(path).config().readout_phases, 3);
  EXPECT_EQ(CompileModel::load(path).segment(trajectories), voted);

  model.set_readout_phases(1);
  const auto single = model.segment(trajectories);
  model.save(model_scratch("one_phase.scm"));
  EXPECT_EQ(CompileModel::load(model_scratch("one_phase.scm")).config().readout_phases, 1);
  EXPECT_NE(single, voted) << "three phases read these trajectories exactly as one";
  EXPECT_THROW(model.set_readout_phases(0), InputError);
  EXPECT_THROW(model.set_readout_phases(17), InputError);
  EXPECT_EQ(model.config().readout_phases, 1);
}

TEST(CompileModel, BadFilesGiveOneLineInputErrors) {
  const auto path = trained_model();
  const std::string good = test::read_bytes(path);

  expect_load_error(model_scratch("missing.scm"), "no such model file");
  const auto truncated = model_scratch("truncated.scm");
  test::write_bytes(truncated, good.substr(0, good.size() - 100));
  expect_load_error(truncated, "checksum");
  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x10);
  const auto corrupt = model_scratch("corrupt.scm");
  test::write_bytes(corrupt, flipped);
  expect_load_error(corrupt, "corrupt");
  std::string newer = good;
  newer[8] = static_cast<char>(kModelFormatVersion + 1);
  const auto future = model_scratch("future.scm");
  test::write_bytes(future, newer);
  expect_load_error(future, "newer than this program supports");

  expect_load_error(path, "trained for task \"parking\", expected \"writing\"", "writing");
  expect_load_error(path, "expects 2-D actions, the task has 3", "", -1, 3);
  expect_load_error(path, "expects 12-D states, the task has 6", "parking", 6, 2);

  // A well-formed file whose config does not match its tensors (e.g. edited by hand).
  ModelFileContents contents = read_model_file(path);
  contents.header["config"]["latent_size"] = 9;
  const auto mismatched = model_scratch("mismatched.scm");
  write_model_file(mismatched, contents);
  expect_load_error(mismatched, "wrong dimensions");
  contents = read_model_file(path);
  contents.header["format"] = "something-else";
  const auto foreign = model_scratch("foreign.scm");
  write_model_file(foreign, contents);
  expect_load_error(foreign, "not a CompILE model");
}

TEST(CompileModel, ReplacingTheFileMidRunLeavesTheLoadedModelIntact) {
  // A model file replaced while the app runs (a retrain saving over it, or a half-copied file): the loaded
  // extractor keeps giving the same skills (nothing is read lazily), a retrain's save is atomic (readers see
  // the old or the new model, never a mix), and a broken replacement fails only the next load, clearly.
  const auto path = trained_model();
  const auto trajectories = data();
  const CompileExtractor running = CompileExtractor::load(path, "parking");
  const auto before = running.extract_all(trajectories);
  const std::string original = test::read_bytes(path);

  CompileConfig other = CompileModel::load(path).config();
  other.seed += 1;
  other.iterations = 1;
  CompileTrainer(other).train(data(), {}).save(path);
  EXPECT_NE(test::read_bytes(path), original);
  EXPECT_EQ(test::temporaries_left_of(path), 0);
  EXPECT_EQ(running.extract_all(trajectories), before);
  EXPECT_NO_THROW(CompileModel::load(path, "parking"));

  test::write_bytes(path, original.substr(0, original.size() / 2));
  EXPECT_EQ(running.extract_all(trajectories), before);
  expect_load_error(path, "truncated model file");
}

// The same states with other actions (what a keyboard does to an expert's motion): only an encoder that reads
// the actions may segment them differently.
TEST(CompileModel, AnEncoderThatReadsStatesOnlySegmentsTheSameMotionAlikeWhateverTheActions) {
  const auto trajectories = data();
  std::vector<StepSequence> other_actions = trajectories;
  for (auto& t : other_actions)
    for (float& a : t.actions) a = a > 0.0f ? 0.7f : -0.7f;
  const CompileModel states_only = CompileModel::load(trained_model(false, "states_only.scm"));
  EXPECT_FALSE(states_only.config().encoder_reads_actions);
  EXPECT_EQ(states_only.segment(trajectories), states_only.segment(other_actions));
  const CompileModel paper = CompileModel::load(trained_model(true, "paper.scm"));
  EXPECT_NE(paper.segment(trajectories), paper.segment(other_actions));
}

}  // namespace
}  // namespace sc
