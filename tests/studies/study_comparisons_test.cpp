// The pairs a study report tests: the paper's pairs present in the study, Adaptive against the rest, every
// pair when asked or when no planned pair is present.
#include "teaching/studies/study_comparisons.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

using Pairs = std::vector<std::pair<std::string, std::string>>;

TEST(StudyComparisons, ThePapersFirstStudy) {
  EXPECT_EQ(
      planned_comparisons({"full-trajectory", "time-heuristic", "skills"}),
      (Pairs{{"skills", "full-trajectory"}, {"skills", "time-heuristic"}, {"time-heuristic", "full-trajectory"}}));
}

TEST(StudyComparisons, TheDrillsStudyAndAdaptive) {
  EXPECT_EQ(planned_comparisons({"skills", "drills", "ind-drills"}),
            (Pairs{{"drills", "skills"}, {"ind-drills", "skills"}, {"ind-drills", "drills"}}));
  EXPECT_EQ(planned_comparisons({"ind-drills", "drills", "adaptive"}),
            (Pairs{{"ind-drills", "drills"}, {"adaptive", "ind-drills"}, {"adaptive", "drills"}}));
}

TEST(StudyComparisons, EveryPairWhenNoPlannedOneOrWhenAsked) {
  EXPECT_EQ(planned_comparisons({"full-trajectory", "ind-drills"}), (Pairs{{"full-trajectory", "ind-drills"}}));
  EXPECT_EQ(planned_comparisons({"skills", "drills", "full-trajectory"}, ComparisonPlan::AllPairs),
            (Pairs{{"skills", "drills"}, {"skills", "full-trajectory"}, {"drills", "full-trajectory"}}));
}

}  // namespace
}  // namespace sc
