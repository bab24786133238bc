#pragma once
// A scripted learner for headless runs (`skillcoach learn`: the session and crash tests; the golden
// screenshots of the trainer): it imitates a reference trial (the expert's, or a drill's) with a
// deterministic, skill-dependent error, so sessions have realistic, reproducible data without a person.
//   parking: the expert's actions with the steering scaled by `skill` and the throttle jittered by a seeded
//            stream (states and rewards dropped: the kit re-simulates them, as for any recorded trial);
//   writing: the gold pen path shifted and wobbled by (1 - skill) x 6 px.
#include <cstdint>
#include <string>

#include "engine/core/json_file.hpp"

namespace sc {

// skill in [0, 1] (1 = the reference itself). `seed` varies the jitter between attempts.
Json scripted_attempt(const Json& reference_trial, double skill, std::uint64_t seed, const std::string& device);
// The same, by a learner who writes in a hand of their own: `hand` 1-15 writes a writing reference's word in
// that Omniglot drawer's letters (at the drawer's size, from the guide's first point) before the error above;
// 0, or a parking reference, is scripted_attempt's. Throws InputError for a word that is not classic.
Json scripted_attempt(const Json& reference_trial, double skill, std::uint64_t seed, const std::string& device,
                      int hand);

}  // namespace sc

#include <functional>

#include "teaching/sessions/training_session.hpp"

namespace sc {

// The scripted learner's whole behaviour in a session: pre-test at skill 0.6, each practice attempt a
// little better (0.7 rising to 0.95), evaluation at 0.85; a demo is recorded before each practice slot.
// A simulated cohort (the study report's test) gives each learner their own levels.
struct ScriptedSkills {
  double pretest = 0.6;
  double practice_start = 0.7;  // + 0.05 per practice attempt, up to practice_end
  double practice_end = 0.95;
  double eval = 0.85;
};
// Plays until `stop(session)` is true or the round's summary is reached. `after_trial` runs after each
// kept trial (the crash test prints there; the CLI may sleep to let a test kill it mid-session).
struct ScriptedRunHooks {
  std::function<bool(const TrainingSession&)> stop;  // optional
  std::function<void(const TrainingSession&, const std::string& kind, const SubmittedTrial&)> after_trial;
  std::function<void(const TrainingSession&)> after_analysis;  // optional: the round's curriculum is made
  ScriptedSkills skills;
  int hand = 0;  // writing tests (pre-test, evaluation) in this Omniglot drawer's letters; 0: the guide's shapes
};
void play_scripted_round(TrainingSession& session, const ScriptedRunHooks& hooks = {});

}  // namespace sc
