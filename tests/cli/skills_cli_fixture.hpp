#pragma once
// Shared by the train-skills / segment / evaluate-skills CLI tests: tiny models trained through the real
// command (a few demonstrations, one or two iterations: about a second each), cached in the build's test output.
#include <filesystem>
#include <string>

#include "engine/core/json_file.hpp"
#include "tests/support/run_skillcoach.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc::test {

// Trains `train-skills --task <task> --demos 6 --iterations 2 --seed <seed>` into the scratch folder, once
// for every build of the program, and returns the model path; fails the calling test (ADD_FAILURE) when the
// command fails.
std::filesystem::path tiny_model(const std::string& task, unsigned seed = 3);

// A writing trial file: a wavy line along the baseline for `word`.
std::filesystem::path wavy_writing_trial(const std::string& name, const std::string& word = "b-a-t---");

// The lines of `text` that are not empty.
int count_lines(const std::string& text);

}  // namespace sc::test
