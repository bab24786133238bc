#include "engine/parking/parking_replay.hpp"

namespace sc {

ParkingReplay replay_parking_trial(const ParkingTrial& trial) {
  ParkingSim sim(trial.scenario);
  ParkingReplay out;
  const std::size_t per_step = trial.control_hz == parking::kSimulationHz ? parking::kSubstepsPerAction : 1;
  std::size_t next = 0;
  while (next + per_step <= trial.actions.size() && !sim.done()) {
    std::array<ParkingAction, parking::kSubstepsPerAction> held{};
    for (std::size_t k = 0; k < held.size(); ++k) held[k] = trial.actions[next + (per_step == 1 ? 0 : k)];
    next += per_step;
    const ParkingStepResult r = sim.step_substeps(held);
    out.steps.push_back({sim.steps(), sim.vehicle(), r.reward, r.success});
    out.total_return += r.reward;
    if (r.success) out.success_step = sim.steps();
    out.collision = out.collision || r.collision;
  }
  out.ignored_actions = static_cast<int>(trial.actions.size() - next);
  return out;
}

}  // namespace sc
