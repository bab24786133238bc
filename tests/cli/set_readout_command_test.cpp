// `skillcoach set-readout` end to end on tiny models: the phases in the file, everything else kept.
#include <gtest/gtest.h>

#include "tests/cli/skills_cli_fixture.hpp"

namespace sc {
namespace {

using test::run_skillcoach;
using test::scratch_path;

std::filesystem::path copy_of(const std::filesystem::path& model, const std::string& name) {
  const auto out = scratch_path("set_readout", name);
  std::filesystem::copy_file(model, out, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(model.string() + ".json", out.string() + ".json",
                             std::filesystem::copy_options::overwrite_existing);
  return out;
}

TEST(SetReadoutCommand, WritesThePhasesAndKeepsTheWeightsAndTheSidecarsRecord) {
  const auto original = test::tiny_model("writing");
  const auto model = copy_of(original, "writing.pt");
  Json recorded = read_json_file(model.string() + ".json");
  recorded["execution_noise_floor"] = {{"value", -0.5}, {"percentile", 1.0}};  // as `--noise-floor --record` writes
  write_json_file(model.string() + ".json", recorded);
  const Json before = read_json_file(model.string() + ".json");
  ASSERT_EQ(before.at("config").at("readout_phases"), 3);  // writing models are trained to read 3

  const auto r = run_skillcoach("set-readout --model " + model.string() + " --phases 1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("reads 1 phase (was 3)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("recalibrate"), std::string::npos) << r.output;
  const Json after = read_json_file(model.string() + ".json");
  EXPECT_FALSE(after.at("config").contains("readout_phases"));  // 1 is the default, written only when not
  EXPECT_EQ(after.at("metrics"), before.at("metrics"));
  EXPECT_EQ(after.at("data"), before.at("data"));
  EXPECT_EQ(after.at("git_revision"), before.at("git_revision"));
  EXPECT_EQ(after.at("execution_noise_floor"), before.at("execution_noise_floor"));
  EXPECT_NE(test::read_bytes(model), test::read_bytes(original));

  // Back to 3: the very file train-skills wrote, so the weights were never touched.
  ASSERT_EQ(run_skillcoach("set-readout --model " + model.string() + " --phases 3").exit_code, 0);
  EXPECT_EQ(test::read_bytes(model), test::read_bytes(original));
  Json again = read_json_file(model.string() + ".json");
  EXPECT_EQ(again.at("model_file"), "writing.pt");  // the copy's own name, where the copied sidecar had the original's
  again["model_file"] = before.at("model_file");
  EXPECT_EQ(again, before);
}

TEST(SetReadoutCommand, RefusesAModelThatDoesNotResampleAndPhasesOutOfRange) {
  const auto parking = copy_of(test::tiny_model("parking"), "parking.pt");
  const std::string bytes = test::read_bytes(parking);
  const auto r = run_skillcoach("set-readout --model " + parking.string() + " --phases 3");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("does not resample"), std::string::npos) << r.output;
  EXPECT_EQ(test::read_bytes(parking), bytes);
  EXPECT_EQ(run_skillcoach("set-readout --model " + parking.string() + " --phases 0").exit_code, 2);
  EXPECT_EQ(run_skillcoach("set-readout --model missing.pt --phases 3").exit_code, 2);
}

}  // namespace
}  // namespace sc
