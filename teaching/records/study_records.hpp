#pragma once
// What the store keeps about a study (a between-subjects experiment such as the paper's human study):
// its definition, and each participant's enrolment with the condition the randomisation assigned.
// A participant's sessions carry the study's name (NewSession::study), so every store that implements
// these records answers the same questions: who is enrolled, in which condition, with which sessions.
#include <cstdint>
#include <string>
#include <vector>

namespace sc::records {

struct StudyDefinition {
  std::string name;                     // unique; how researchers and `skillcoach learn --study` name it
  std::string task;                     // "parking" or "writing": every session of the study is of this task
  std::vector<std::string> conditions;  // condition keys ("skills", "time-heuristic", ...), 2 or more, distinct
  int target_per_condition = 0;         // participants wanted in each condition
  std::uint64_t seed = 0;               // seeds the randomisation (study_assignment.hpp)
  std::string created;                  // ISO-8601 UTC

  int capacity() const { return target_per_condition * static_cast<int>(conditions.size()); }
};

struct StudyParticipant {
  std::string learner;
  int seq = 0;            // 1-based enrolment order within the study
  std::string condition;  // assigned at enrolment, never changed
  std::string enrolled;   // ISO-8601 UTC
};

// Participants per condition against the target, in the study's condition order.
struct ConditionEnrolment {
  std::string condition;
  int enrolled = 0;
  int target = 0;
};

}  // namespace sc::records
