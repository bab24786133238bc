#include "app/core/training_progress_bar.hpp"

#include <gtest/gtest.h>

namespace sc::cli {
namespace {

TEST(TrainingProgressLine, NamesTheWarmStartAndItsBoundaryCrossEntropy) {
  TrainingProgress p;
  p.iteration = 3;
  p.iterations = 100;
  p.warm_start = true;
  p.boundary_ce = 2.5;
  const std::string line = describe_training_progress(p);
  EXPECT_EQ(line.rfind("warm start 3/100", 0), 0u) << line;
  EXPECT_NE(line.find("boundary_ce 2.5)"), std::string::npos) << line;
  p.unit_ce = 0.75;
  EXPECT_NE(describe_training_progress(p).find("boundary_ce 2.5 unit_ce 0.75)"), std::string::npos);
  p.warm_start = false;
  EXPECT_EQ(describe_training_progress(p).find("boundary_ce"), std::string::npos);
}

TEST(TrainingProgressLine, EtaCountsOnlyTheCurrentPhase) {
  // 100 s of warm start, then 10 of 60 iterations in 20 s: 50 more take 100 s, not (120 / 10) x 50.
  TrainingProgress p;
  p.iteration = 10;
  p.iterations = 60;
  p.elapsed_seconds = 120.0;
  p.phase_start_seconds = 100.0;
  const std::string line = describe_training_progress(p);
  EXPECT_NE(line.find("ETA 100 s"), std::string::npos) << line;
}

}  // namespace
}  // namespace sc::cli
