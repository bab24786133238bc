#pragma once
// Parking trials as the step sequences the SkillExtractor reads: the reference's 12-D rollout state before
// each action and the 2-D action (reference-facts §1.6, §3.2).
#include <vector>

#include "engine/parking/parking_sim.hpp"
#include "engine/parking/parking_trial.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

inline constexpr int kParkingStateDim = 12;
inline constexpr int kParkingActionDim = 2;

// states: T+1 (or T) observations, actions: T control-rate actions. Uses the first T states.
StepSequence parking_step_sequence(const std::vector<ParkingObservation>& states,
                                   const std::vector<ParkingAction>& actions);

// A trial file's steps. Missing states are re-simulated from the scenario. Trials recorded at the
// simulation rate (control_hz 15, "responsive" input) are reduced to the control rate: the mean of each
// control step's three actions, the state before its first sub-step.
StepSequence parking_step_sequence(const ParkingTrial& trial);

// The car state an observation describes (position x100, heading from cos/sin, signed speed from the
// velocity projected on the heading), e.g. to start a drill where an expert segment starts.
VehicleState vehicle_from_observation(const ParkingObservation& observation);

}  // namespace sc
