#pragma once
// `skillcoach simulate-students --task writing`: the synthetic-student experiment on the writing task
// (teaching/students/writing_student_experiment.hpp). simulate_students_command.cpp parses the shared
// options and dispatches here.
#include <CLI/CLI.hpp>

#include <string>

namespace sc::cli {

struct WritingSimulateArgs {
  unsigned long long seed = 0;
  std::string out_dir;
  std::string model;
  int pairs = 0;
  double rehearsal = 0.0;
  bool quick = false;
  int finetune_epochs = 0;              // 0: the experiment's default
  double finetune_learning_rate = 0.0;  // 0: the experiment's default
  int words_per_set = 0;                // 0: the experiment's default
  int targets = 0;                      // 0: the experiment's default
};

// The writing-only options (ignored with --task parking); --finetune-epochs and --finetune-lr are shared
// with parking and copied into the args by simulate_students_command.cpp.
void add_writing_student_options(CLI::App& sub, WritingSimulateArgs& args);

// Prints the table, writes <out_dir>/writing_students.json and writing_students.png; returns 0.
int run_writing_students(const WritingSimulateArgs& args);

}  // namespace sc::cli
