#include "teaching/tasks/parking_drill_projector.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/parking/parking_expert.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {

ParkingDrillProjector::ParkingDrillProjector(std::vector<ParkingTrial> experts) : experts_(std::move(experts)) {
  expert_steps_.reserve(experts_.size());
  for (std::size_t i = 0; i < experts_.size(); ++i) {
    if (experts_[i].states.size() != experts_[i].actions.size() + 1 || experts_[i].control_hz != parking::kControlHz)
      throw InputError("parking drill projector",
                       "expert " + std::to_string(i) + " needs control-rate actions and T+1 recorded states");
    expert_steps_.push_back(parking_step_sequence(experts_[i]));
  }
}

ParkingScenario ParkingDrillProjector::drill_scenario(const DrillPlan& plan) const {
  // Validates the plan (indices, intervals) before anything is indexed.
  concatenate_expert_steps(plan, expert_steps_);
  const DrillSegment& first = plan.segments.front();
  // The recorded double-precision observation, not the float copy in the step sequence.
  const VehicleState start = vehicle_from_observation(experts_[first.expert].states[first.begin]);
  ParkingScenario scenario = experts_[plan.segments.back().expert].scenario;
  scenario.start = start;
  scenario.heading0 = start.heading;
  return scenario;
}

std::vector<ParkingAction> ParkingDrillProjector::drill_actions(const DrillPlan& plan) const {
  std::vector<ParkingAction> actions;
  for (const DrillSegment& s : plan.segments)
    for (int t = s.begin; t < s.end; ++t) actions.push_back(experts_[s.expert].actions[t]);
  return actions;
}

PlayableDrill ParkingDrillProjector::project(const DrillPlan& plan) const {
  const ParkingScenario scenario = drill_scenario(plan);  // validates the plan before drill_actions indexes it
  const ParkingPlan run = simulate_plan(scenario, drill_actions(plan));
  PlayableDrill drill;
  drill.plan = plan;
  drill.steps = parking_step_sequence(run.states, run.actions);
  const ParkingObservation& last = run.states.back();
  drill.final_state.assign(last.begin(), last.end());
  for (const ParkingObservation& o : run.states) drill.ghost_path.push_back({o[0] * 100.0, o[1] * 100.0});
  const int executed = static_cast<int>(run.actions.size());
  for (int start : plan.segment_starts()) drill.segment_starts.push_back(std::min(start, executed));
  drill.drill_return = run.rewards.empty() ? parking_reward(run.states.front()) : run.rewards.back();
  drill.success = run.success;
  return drill;
}

ParkingTrial ParkingDrillProjector::drill_trial(const PlayableDrill& drill) const {
  // Re-simulated from the plan's double-precision actions (the step sequence holds floats), so the
  // trial's states are exactly the ghost's.
  const ParkingScenario scenario = drill_scenario(drill.plan);
  ParkingTrial trial = simulate_plan(scenario, drill_actions(drill.plan)).to_trial(scenario);
  trial.source = "drill";
  return trial;
}

}  // namespace sc
