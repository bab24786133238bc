#pragma once
// The train-skills progress display on stderr: on a terminal one line rewritten in place (iteration, loss
// terms, validation NLL, ETA); otherwise (a log file, CI) plain lines, one per validation check and one
// for the last iteration, so logs stay readable.
#include <cstdio>
#include <string>

#include "teaching/skills/compile_trainer.hpp"

namespace sc::cli {

// "it 12/60  loss 3.21 (nll_a 2.90 nll_s 0.00 kl_z 0.21 kl_b 0.10)  valid 2.95 (best 2.95)  12.3 s  ETA 49 s"
std::string describe_training_progress(const TrainingProgress& progress);

class TrainingProgressBar {
 public:
  explicit TrainingProgressBar(std::FILE* out);
  void update(const TrainingProgress& progress);
  // Ends the in-place line (if any) so later output starts on a fresh line.
  void finish();

 private:
  std::FILE* out_;
  bool terminal_;
  bool line_open_ = false;
  std::size_t last_width_ = 0;
};

}  // namespace sc::cli
