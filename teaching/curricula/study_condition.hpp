#pragma once
// The paper's study conditions (§5) plus our Adaptive one; names as printed in the paper's figures.
#include <array>
#include <string>
#include <string_view>

namespace sc {

enum class StudyCondition { FullTrajectory, TimeHeuristic, Skills, Drills, IndDrills, Adaptive };

inline constexpr std::array<StudyCondition, 6> kAllStudyConditions = {
    StudyCondition::FullTrajectory, StudyCondition::TimeHeuristic, StudyCondition::Skills,
    StudyCondition::Drills,         StudyCondition::IndDrills,     StudyCondition::Adaptive};

// "Full Trajectory", "Time Heuristic", "Skills", "Drills", "Ind. Drills", "Adaptive".
std::string_view condition_name(StudyCondition condition);
// "full-trajectory", "time-heuristic", "skills", "drills", "ind-drills", "adaptive" (CLI, JSON, database).
std::string_view condition_key(StudyCondition condition);
// Accepts a key or a display name, case-insensitively; InputError listing the valid keys otherwise.
StudyCondition parse_condition(std::string_view text);

}  // namespace sc
