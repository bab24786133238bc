#include "teaching/curricula/study_condition.hpp"

#include <cctype>

#include "engine/core/error.hpp"

namespace sc {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::string_view condition_name(StudyCondition condition) {
  switch (condition) {
    case StudyCondition::FullTrajectory:
      return "Full Trajectory";
    case StudyCondition::TimeHeuristic:
      return "Time Heuristic";
    case StudyCondition::Skills:
      return "Skills";
    case StudyCondition::Drills:
      return "Drills";
    case StudyCondition::IndDrills:
      return "Ind. Drills";
    case StudyCondition::Adaptive:
      return "Adaptive";
  }
  return "?";
}

std::string_view condition_key(StudyCondition condition) {
  switch (condition) {
    case StudyCondition::FullTrajectory:
      return "full-trajectory";
    case StudyCondition::TimeHeuristic:
      return "time-heuristic";
    case StudyCondition::Skills:
      return "skills";
    case StudyCondition::Drills:
      return "drills";
    case StudyCondition::IndDrills:
      return "ind-drills";
    case StudyCondition::Adaptive:
      return "adaptive";
  }
  return "?";
}

StudyCondition parse_condition(std::string_view text) {
  const std::string wanted = lower(text);
  std::string keys;
  for (StudyCondition c : kAllStudyConditions) {
    if (wanted == condition_key(c) || wanted == lower(condition_name(c))) return c;
    keys += (keys.empty() ? "" : ", ") + std::string(condition_key(c));
  }
  throw InputError("study condition '" + std::string(text) + "'", "unknown; expected one of " + keys);
}

}  // namespace sc
