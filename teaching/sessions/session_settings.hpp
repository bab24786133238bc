#pragma once
// What a training session was started with. Stored as the session's settings_json so that a resumed
// session regenerates exactly the same scenarios and curricula (everything else derives from the seed).
#include <cstdint>
#include <string>

#include "engine/core/json_file.hpp"
#include "teaching/curricula/study_condition.hpp"

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

  void validate() const;  // InputError for an empty learner/device, counts outside 1..50, weak_skills
                          // outside 1..10 or drills_per_weak_skill outside 1..5
};

// {"pretest_count":5, "eval_count":5, "device":"keyboard", "weak_skills":3, "drills_per_weak_skill":2}
// (learner, condition and seed have their own columns in the sessions table).
Json settings_to_json(const SessionSettings& settings);
// Fills the counts and device from `settings_json` (missing members keep their defaults, so sessions
// recorded before a member existed resume with today's default).
void read_settings_json(const JsonView& view, SessionSettings& settings);

}  // namespace sc
