#pragma once
// ParkingExpert: the demonstrator. No training: it plans with the known dynamics.
//  1. search_manoeuvres(): a tree of two-phase motion primitives gives a few topologically different
//     initial guesses (forward / reverse first, left / right);
//  2. ActionSequenceOptimizer: Levenberg-Marquardt on each guess's 5 Hz action sequence (goal pose,
//     smooth actions, slow arrival, clearance to obstacles at every sub-step);
//  3. horizon shrinking: the best sequence is re-optimised one control step shorter (time-rescaled) while
//     ParkingSim still reports success without collision, so the plan is about as short as the car allows;
//  4. every candidate is judged by ParkingSim itself (exact dynamics, Box2D collisions); the plan returned
//     is what ParkingSim produces for its actions.
// Deterministic: same scenario and options, same plan (only planning_ms varies).
#include <vector>

#include "engine/parking/action_sequence_optimizer.hpp"
#include "engine/parking/collision_checker.hpp"
#include "engine/parking/parking_sim.hpp"
#include "engine/parking/parking_trial.hpp"

namespace sc {

struct ParkingExpertOptions {
  PlanningCostWeights weights;
  int max_steps = 40;          // longest plan considered (control steps)
  int guesses = 5;             // manoeuvre classes optimised directly for the goal
  int staged_guesses = 7;      // manoeuvre classes optimised through the staging pose
  int refine_best = 2;         // candidates whose horizon is shrunk
  int first_iterations = 60;   // LM iterations from a primitive guess
  int shrink_iterations = 25;  // LM iterations per shrink step
  int roll_in_steps = 6;       // straight steps appended after the staging pose (obstacle-aware strategy)
  double roll_in_speed = 4.0;  // m/s towards the spot at the staging pose
  // Extra control steps added back after the shortest successful horizon, for a slower, straighter
  // arrival. 0 by default: on random classic scenarios one extra step raises the mean steps to success
  // from ~17.4 to ~18.1 (the target is <= 18); the arrival-speed term already slows the car down.
  int careful_extra_steps = 0;
};

struct ParkingPlan {
  std::vector<ParkingAction> actions;      // T actions, up to the end of the episode
  std::vector<ParkingObservation> states;  // T+1 observations (start included)
  std::vector<double> rewards;             // T rewards
  bool success = false;
  int success_step = -1;  // 1-based, -1 when not reached
  bool collision = false;
  double planning_ms = 0.0;  // CPU time of the planning thread

  double total_return() const;
  ParkingTrial to_trial(const ParkingScenario& scenario) const;  // source "expert"
};

class ParkingExpert {
 public:
  explicit ParkingExpert(ParkingExpertOptions options = {});
  ParkingPlan plan(const ParkingScenario& scenario) const;

 private:
  struct Candidate {
    Eigen::VectorXd z;
    ParkingPlan plan;
  };
  std::vector<Candidate> direct_candidates(const ParkingScenario& scenario, const CollisionChecker& collisions,
                                           ActionSequenceOptimizer& optimizer) const;
  std::vector<Candidate> staged_candidates(const ParkingScenario& scenario, const CollisionChecker& collisions,
                                           ActionSequenceOptimizer& optimizer) const;
  ParkingPlan shorten(const ParkingScenario& scenario, ActionSequenceOptimizer& optimizer,
                      const Candidate& candidate) const;

  ParkingExpertOptions options_;
};

// Better plan first: clean success (no collision), then fewer steps, then higher return.
bool better_plan(const ParkingPlan& a, const ParkingPlan& b);

// Runs `actions` in ParkingSim until the episode ends; the plan holds what actually happened.
ParkingPlan simulate_plan(const ParkingScenario& scenario, const std::vector<ParkingAction>& actions);

}  // namespace sc
