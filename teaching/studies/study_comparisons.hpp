#pragma once
// Which pairs of conditions a study report tests. The paper's human study (§5) compared, per task:
// Skills vs Full Trajectory, Skills vs Time Heuristic and Time Heuristic vs Full Trajectory (does skill
// discovery help?), and Drills vs Skills, Ind. Drills vs Skills and Ind. Drills vs Drills (do drills, and
// individualised drills, help?). A report tests those of them whose two conditions are both in the study,
// plus our Adaptive condition against every other condition of the study; when none of these pairs is in
// the study, or when every pair is asked for, it tests every pair. The first condition of a pair is the one
// whose U statistic is reported.
#include <string>
#include <utility>
#include <vector>

namespace sc {

enum class ComparisonPlan { Paper, AllPairs };

// Pairs of condition keys, in the order above (then the study's order).
std::vector<std::pair<std::string, std::string>> planned_comparisons(const std::vector<std::string>& conditions,
                                                                     ComparisonPlan plan = ComparisonPlan::Paper);

}  // namespace sc
