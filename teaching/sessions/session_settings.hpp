#pragma once
// What a training session was started with. Stored as the session's settings_json so that a resumed
// session regenerates exactly the same scenarios and curricula (everything else derives from the seed).
#include <cstdint>
#include <optional>
#include <string>

#include "engine/core/json_file.hpp"
#include "engine/parking/parking_scenario.hpp"
#include "teaching/curricula/study_condition.hpp"
#include "teaching/records/record_types.hpp"

namespace sc {

struct SessionSettings {
  std::string learner;                                  // name shown on the welcome screen
  std::string device = "keyboard";                      // recorded with every trial
  StudyCondition condition = StudyCondition::Adaptive;  // learners get Adaptive; research mode picks
  int pretest_count = 5;                                // N_s (Alg. 1)
  int eval_count = 5;                                   // fresh evaluation scenarios per round
  int weak_skills = 3;                                  // drills for the 3 weakest skills per round ...
  int drills_per_weak_skill = 2;                        // ... 2 unique drills each (Ind. Drills, Adaptive)
  std::uint64_t seed = 20221128;
  // Parking: where the goals of the pre-test, drills and evaluation lie. The paper's user study used the
  // study corner (3 spots) because the whole lot needs many more skills; a learner's first parking session
  // uses it too (first_session_goal_region), later sessions and free practice the whole lot. Writing: none.
  std::optional<GoalRegion> goal_region;
  // The study this session is part of (empty: none); `condition` is then the learner's assigned one.
  std::string study;
  GoalRegion lot() const { return goal_region.value_or(GoalRegion::WholeLot); }

  void validate() const;  // InputError for an empty learner/device, counts outside 1..50, weak_skills
                          // outside 1..10 or drills_per_weak_skill outside 1..5
};

// {"pretest_count":5, "eval_count":5, "device":"keyboard", "weak_skills":3, "drills_per_weak_skill":2,
//  "goal_region":"study-corner" (parking only)} (learner, condition and seed have their own columns in the sessions
//  table).
Json settings_to_json(const SessionSettings& settings);
// Fills the counts and device from `settings_json` (missing members keep their defaults, so sessions
// recorded before a member existed resume with today's default).
void read_settings_json(const JsonView& view, SessionSettings& settings);
// A stored session's settings (its columns and settings_json), validated; InputError naming the session.
SessionSettings settings_of_session(const records::SessionRow& row);

// The lot of a new parking session when nobody chose one: the study corner for a learner's first parking
// session (`earlier_parking_sessions` == 0), the whole lot afterwards.
GoalRegion first_session_goal_region(int earlier_parking_sessions);

}  // namespace sc
