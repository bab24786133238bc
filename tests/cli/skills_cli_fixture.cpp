#include "tests/cli/skills_cli_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace sc::test {

std::filesystem::path tiny_model(const std::string& task, unsigned seed) {
  const auto model = scratch_path("skills_cli", "tiny_" + task + "_" + std::to_string(seed) + ".pt");
  // Kept between test processes, but only while it is newer than the program: a model left by an older build
  // (another config, another file format) would test the old program's output.
  if (std::filesystem::exists(model) &&
      std::filesystem::last_write_time(model) >= std::filesystem::last_write_time(skillcoach_binary()))
    return model;
  // Writing: 2 warm-start passes (not the default 60) and one run, so the tiny model stays quick.
  const std::string writing =
      task == "writing" ? " --set warm_start_iterations=2 --set restarts=1 --noise-floor-learners 0" : "";
  const CommandResult r = run_skillcoach("train-skills --task " + task + " --demos 6 --iterations 2 --seed " +
                                         std::to_string(seed) + writing + " --out " + model.string());
  if (r.exit_code != 0) ADD_FAILURE() << "train-skills failed: " << r.output;
  return model;
}

std::filesystem::path wavy_writing_trial(const std::string& name, const std::string& word) {
  const auto file = scratch_path("skills_cli", name);
  Json doc = {{"task", "writing"}, {"scenario", {{"word", word}}}, {"points", Json::array()}};
  for (int x = 0; x <= 400; x += 4) doc["points"].push_back({x, 150.0 + 20.0 * std::sin(x / 25.0)});
  write_json_file(file, doc);
  return file;
}

int count_lines(const std::string& text) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += !line.empty();
  return n;
}

}  // namespace sc::test
