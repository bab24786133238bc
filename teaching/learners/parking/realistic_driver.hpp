#pragma once
// Realistic parking drivers: an expert drive as a novice would reproduce it with a real input device, so
// that skill models, diagnoses and tests meet the input real learners give (the diagnosis must hold on
// novice learners, not only on near-perfect copies of the expert).
//
// Spec. The driver follows the expert's control-rate actions, open loop (no correction, the default) or
// watching the path (`follows_path`: the expert's action plus path_follower.hpp's correction), with
//  * a reaction delay: at time t it does what the expert did at t - delay (neutral before the start);
//    a driver who follows the path also corrects what it saw at t - delay: the correction for the car's
//    state then, against where the expert was at t - 2 delay (what it would have decided at t - delay);
//  * stick noise: a slow wander on each axis (first-order autoregressive, time constant
//    `noise_time_constant_s`, standard deviation `stick_noise` in action units) on top of the intent;
//  * the device between intent and action, with the app's own mappings (engine/input/):
//      gamepad  - the stick is aimed at square_to_disc(intent) + wander, then map_gamepad's radial dead zone
//                 (0.12) and disc->square map;
//      mouse    - the on-screen joystick's knob at the same point, action_for_knob (no dead zone);
//      keyboard - intent + wander per axis, a key is held when it reaches half the key action, giving
//                 {-1, 0, +1} (KeyboardDrive::kKeyAction): the quantisation of a keyboard; a driver who uses
//                 Shift (`shift_for_gentle_steering`) steers at the nearest of {0, +-0.5, +-1} instead;
//  * the input rate: control_hz 15 records one action per 1/15 s sub-step (the app's "responsive" mode,
//    the recorded trial has control_hz 15), control_hz 5 one per 0.2 s control step;
//  * optionally a planted deficit (PlantedDeficit), applied last, to the action the car receives; a late
//    braker's coasted samples get no correction of the pedal either.
// The drive lasts the expert's steps plus the delay, and stops early at success, collision or the horizon.
// Deterministic in the Rng given.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/rng.hpp"
#include "engine/parking/parking_trial.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

enum class DriveDevice { Gamepad, MouseJoystick, Keyboard };
std::string device_name(DriveDevice device);  // "gamepad", "mouse", "keyboard" (the trial's "device")

// A weakness planted in a driver, to check that the diagnosis finds it.
enum class PlantedDeficit {
  None,
  NeverReversing,  // where the expert accelerates backwards the driver only brakes to a stop, never below 0
  WeakSteering,    // |u1| <= kWeakSteering: never more than half lock
  LateBraking,     // the first kLateBrakingSeconds of every expert braking run are coasted (u0 = 0)
};
std::string deficit_name(PlantedDeficit deficit);  // "none", "never-reversing", "weak-steering", "late-braking"

inline constexpr double kWeakSteering = 0.5;
inline constexpr double kLateBrakingSeconds = 0.6;

struct RealisticDriverProfile {
  DriveDevice device = DriveDevice::Gamepad;
  int control_hz = 15;                 // 15 or 5 (parking::kSimulationHz or parking::kControlHz)
  double stick_noise = 0.15;           // wander standard deviation, action units
  double noise_time_constant_s = 0.3;  // wander correlation time
  double reaction_delay_s = 0.2;       // >= 0
  // Standing still before the first input, on top of the reaction delay (>= 0): a learner after the countdown.
  // Open loop it only delays the drive further; a driver who follows the path still reacts after
  // reaction_delay_s to what it sees.
  double start_wait_s = 0.0;
  // After the expert's last input: brake to a standstill and stand this long (>= 0), as a learner who has given up
  // on the spot does until the trainer's time limit.
  double end_wait_s = 0.0;
  // After the expert's last input: drive on towards where the expert's drive ended (the path follower's greedy
  // correction), until the trial has lasted this long (0: stop with the plan), as a learner who has not parked does
  // until the trainer's time limit. end_wait_s, when set, comes first.
  double keeps_trying_until_s = 0.0;
  PlantedDeficit deficit = PlantedDeficit::None;
  bool follows_path = false;               // closes the loop on the expert's path (path_follower.hpp); draws no numbers
  bool shift_for_gentle_steering = false;  // keyboard only: holds Shift for half lock (KeyboardDrive::kGentleSteer)
};

// A novice on `device` at 15 Hz: stick noise uniform in [0.05, 0.2], delay uniform in [0.1, 0.3] s (human
// reaction to a cue one already expects), time constant 0.3 s. Draws 2 numbers from rng.
RealisticDriverProfile sample_novice_profile(DriveDevice device, Rng& rng);

// The expert's drive as `profile` drives it. `expert` needs control-rate actions (control_hz 5).
// Records control_hz, actions (at that rate), T+1 states, T rewards, success, source "learner", device.
// Throws InputError if the expert trial is not at the control rate or the profile is out of range.
ParkingTrial realistic_drive(const ParkingTrial& expert, const RealisticDriverProfile& profile, Rng& rng);

// The keys a keyboard driver holds for `intent`, per axis: a key when the intent reaches half the key action,
// giving {-1, 0, +1} (KeyboardDrive::kKeyAction); with Shift for gentle steering the steering is the nearest of
// {0, +-0.5, +-1} (KeyboardDrive::kGentleSteer).
ParkingAction keyboard_keys(const ParkingAction& intent, bool shift_for_gentle_steering = false);
// The same control steps with keyboard_keys for every (u0, u1) action and the states kept: the expert's
// motion read through keyboard values (keyed copies in training, keyed_action_agreement).
StepSequence with_keyboard_keys(StepSequence steps);

// The expert's control steps that brake: acceleration against the motion, |u0| >= 0.15 while moving
// (|speed| >= 0.5 m/s) - the runs LateBraking delays. Uses the trial's states (re-simulated if missing).
std::vector<bool> expert_braking_steps(const ParkingTrial& expert);

}  // namespace sc
