#include "teaching/learners/parking/realistic_driver.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "engine/core/error.hpp"
#include "engine/input/gamepad_mapping.hpp"
#include "engine/input/keyboard_drive.hpp"
#include "engine/input/stick_geometry.hpp"
#include "engine/input/virtual_joystick.hpp"
#include "teaching/learners/parking/path_follower.hpp"

namespace sc {
namespace {

constexpr double kMovingSpeed = 0.5;  // m/s, as parking_skill_motion's words
constexpr double kBraking = 0.15;     // |u0| against the motion

// The stick's slow wander: one AR(1) process per axis, advanced once per input sample.
class Wander {
 public:
  Wander(double sigma, double time_constant_s, int hz)
      : sigma_(sigma), keep_(time_constant_s > 0.0 ? std::exp(-1.0 / (time_constant_s * hz)) : 0.0) {}
  input::Vec2 next(Rng& rng) {
    const double fresh = sigma_ * std::sqrt(1.0 - keep_ * keep_);
    value_.x = keep_ * value_.x + fresh * rng.normal();
    value_.y = keep_ * value_.y + fresh * rng.normal();
    return value_;
  }
  void start(Rng& rng) { value_ = {sigma_ * rng.normal(), sigma_ * rng.normal()}; }

 private:
  double sigma_;
  double keep_;
  input::Vec2 value_;
};

// Intent (u0, u1) plus wander through the device. Wander x is steering, y is throttle (up = forward).
ParkingAction through_device(const RealisticDriverProfile& p, const ParkingAction& intent, input::Vec2 wander) {
  const DriveDevice device = p.device;
  if (device == DriveDevice::Keyboard)
    return keyboard_keys({intent[0] + wander.y, intent[1] + wander.x}, p.shift_for_gentle_steering);
  const input::Vec2 aim = input::square_to_disc({std::clamp(intent[1], -1.0, 1.0), std::clamp(intent[0], -1.0, 1.0)});
  const input::Vec2 stick{aim.x + wander.x, aim.y + wander.y};
  if (device == DriveDevice::Gamepad) {
    const input::Vec2 held = input::clamp_to_unit_disc(stick);
    const input::InputReading r = input::map_gamepad({held.x, -held.y, 0.0, 0.0}, input::GamepadConfig{});
    return {r.action.accel, r.action.steer};
  }
  const input::DriveAction a = input::action_for_knob({stick.x, -stick.y}, {0.0, 0.0}, 1.0);  // screen y down
  return {a.accel, a.steer};
}

std::vector<double> expert_speeds(const ParkingTrial& expert) {
  ParkingSim sim(expert.scenario);
  std::vector<double> speeds;
  for (const ParkingAction& u : expert.actions) {
    speeds.push_back(sim.vehicle().speed);
    if (!sim.done()) sim.step(u);
  }
  return speeds;
}

void check(const ParkingTrial& expert, const RealisticDriverProfile& p) {
  if (expert.control_hz != parking::kControlHz)
    throw InputError("realistic driver", "the expert drive must be at the control rate (control_hz 5)");
  if (p.control_hz != parking::kControlHz && p.control_hz != parking::kSimulationHz)
    throw InputError("realistic driver", "control_hz must be 5 or 15, got " + std::to_string(p.control_hz));
  if (!(p.stick_noise >= 0.0) || !(p.reaction_delay_s >= 0.0) || !(p.noise_time_constant_s >= 0.0) ||
      !(p.start_wait_s >= 0.0) || !(p.end_wait_s >= 0.0) || !(p.keeps_trying_until_s >= 0.0) ||
      !std::isfinite(p.stick_noise + p.reaction_delay_s + p.noise_time_constant_s + p.start_wait_s + p.end_wait_s +
                     p.keeps_trying_until_s))
    throw InputError("realistic driver", "noise, time constant, delay and waits must be finite and >= 0");
}

// The drive's clock, in input samples.
struct DriveTiming {
  int per_step = 1;             // input samples per control step
  int delay = 0, wait = 0;      // reaction delay and standing start
  int end_wait = 0;             // standing at the end
  int expert_samples = 0;       // the expert's inputs
  int samples = 0;              // the whole drive
  int substeps_per_sample = 0;  // simulation substeps per input sample
  bool keeps_trying = false;    // on after the plan (an end wait comes first)
};

DriveTiming drive_timing(const ParkingTrial& expert, const RealisticDriverProfile& p) {
  DriveTiming t;
  t.per_step = p.control_hz == parking::kControlHz ? 1 : parking::kSubstepsPerAction;
  t.delay = static_cast<int>(std::lround(p.reaction_delay_s * p.control_hz));
  t.wait = static_cast<int>(std::lround(p.start_wait_s * p.control_hz));
  t.end_wait = static_cast<int>(std::lround(p.end_wait_s * p.control_hz));
  t.expert_samples = static_cast<int>(expert.actions.size()) * t.per_step;
  t.keeps_trying = p.keeps_trying_until_s > 0.0 && t.end_wait == 0;
  t.samples = std::max(t.expert_samples + t.delay + t.wait + t.end_wait,
                       t.keeps_trying ? static_cast<int>(std::lround(p.keeps_trying_until_s * p.control_hz)) : 0);
  t.substeps_per_sample = parking::kSubstepsPerAction / t.per_step;
  return t;
}

// What the driver means to do at each input sample, before the device and its deficit: the expert's input it is
// reproducing (late braking held off, corrected towards the path when it follows it), then on towards the expert's
// end or braking to a stand.
class DriverIntent {
 public:
  DriverIntent(const ParkingTrial& expert, const RealisticDriverProfile& p, const DriveTiming& t)
      : expert_(expert),
        p_(p),
        t_(t),
        late_(static_cast<int>(std::lround(kLateBrakingSeconds * p.control_hz))),
        braking_(p.deficit == PlantedDeficit::LateBraking ? expert_braking_steps(expert) : std::vector<bool>{}),
        follower_(p.follows_path || t.keeps_trying ? std::optional<PathFollower>(std::in_place, expert)
                                                   : std::nullopt) {}

  bool follows() const { return follower_.has_value(); }

  // Sample `source` of the expert's inputs (it may lie before or past them); `seen`: the car at the start of each
  // input sample so far; `speed`: the car's speed now.
  ParkingAction at(int source, const std::vector<VehicleState>& seen, double speed) {
    ParkingAction intent{0.0, 0.0};
    if (source >= 0 && source < t_.expert_samples) intent = reproduced(source, seen);
    // Past the expert's last input: on towards where the expert ended, as the driver saw the car a delay ago ...
    if (t_.keeps_trying && source >= t_.expert_samples)
      intent = follower_->correction(seen[static_cast<std::size_t>(source + t_.wait)], follower_->substeps());
    // ... or brake within this sample, then stand (the stick at rest, noise and all).
    if (t_.end_wait > 0 && source >= t_.expert_samples)
      intent[0] = std::clamp(-speed / (parking::kMaxAcceleration / p_.control_hz), -1.0, 1.0);
    return intent;
  }

 private:
  ParkingAction reproduced(int source, const std::vector<VehicleState>& seen) {
    const std::size_t step = static_cast<std::size_t>(source / t_.per_step);
    ParkingAction intent = clip_action(expert_.actions[step]);
    braking_run_ = !braking_.empty() && braking_[step] ? braking_run_ + 1 : 0;
    if (p_.follows_path) {
      // What it decided a reaction delay ago: from the car it saw then, towards where the expert was a delay before.
      const ParkingAction d = follower_->correction(seen[static_cast<std::size_t>(source + t_.wait)],
                                                    (source - t_.delay) * t_.substeps_per_sample);
      intent = clip_action({intent[0] + d[0], intent[1] + d[1]});
    }
    if (braking_run_ > 0 && braking_run_ <= late_) intent[0] = 0.0;
    return intent;
  }

  const ParkingTrial& expert_;
  const RealisticDriverProfile& p_;
  const DriveTiming& t_;
  int late_;
  std::vector<bool> braking_;
  int braking_run_ = 0;  // input samples since the current expert braking run began
  std::optional<PathFollower> follower_;
};

// The device's output with the planted deficit: weak steering clamps the wheel; a driver who never reverses brakes at
// most hard enough to stop within this input sample, never below zero speed.
ParkingAction with_deficit(ParkingAction u, PlantedDeficit deficit, double speed, int control_hz) {
  if (deficit == PlantedDeficit::WeakSteering) u[1] = std::clamp(u[1], -kWeakSteering, kWeakSteering);
  if (deficit == PlantedDeficit::NeverReversing && u[0] < 0.0)
    u[0] = std::max(u[0], -std::max(speed, 0.0) / (parking::kMaxAcceleration / control_hz));
  return u;
}

}  // namespace

std::string device_name(DriveDevice device) {
  switch (device) {
    case DriveDevice::Gamepad:
      return "gamepad";
    case DriveDevice::MouseJoystick:
      return "mouse";
    case DriveDevice::Keyboard:
      return "keyboard";
  }
  return "gamepad";
}

std::string deficit_name(PlantedDeficit deficit) {
  switch (deficit) {
    case PlantedDeficit::None:
      return "none";
    case PlantedDeficit::NeverReversing:
      return "never-reversing";
    case PlantedDeficit::WeakSteering:
      return "weak-steering";
    case PlantedDeficit::LateBraking:
      return "late-braking";
  }
  return "none";
}

RealisticDriverProfile sample_novice_profile(DriveDevice device, Rng& rng) {
  RealisticDriverProfile p;
  p.device = device;
  p.stick_noise = rng.uniform(0.05, 0.2);
  p.reaction_delay_s = rng.uniform(0.1, 0.3);
  return p;
}

std::vector<bool> expert_braking_steps(const ParkingTrial& expert) {
  const std::vector<double> speeds = expert_speeds(expert);
  std::vector<bool> out(expert.actions.size(), false);
  for (std::size_t t = 0; t < out.size(); ++t) {
    const double u0 = clip_action(expert.actions[t])[0];
    out[t] = std::abs(speeds[t]) >= kMovingSpeed && u0 * speeds[t] < 0.0 && std::abs(u0) >= kBraking;
  }
  return out;
}

ParkingAction keyboard_keys(const ParkingAction& intent, bool shift_for_gentle_steering) {
  using input::DriveKey;
  constexpr double key = input::KeyboardDrive::kKeyAction, gentle = input::KeyboardDrive::kGentleSteer;
  // Shift when the steering is nearer half lock than full; a key once the intent reaches half of what it gives.
  const bool shift = shift_for_gentle_steering && std::abs(intent[1]) < 0.5 * (gentle + key);
  const double steer_key = shift ? gentle : key;
  input::KeyboardDrive keys;  // the app's own mapping from held keys to the action
  keys.set_pressed(DriveKey::Up, intent[0] >= 0.5 * key);
  keys.set_pressed(DriveKey::Down, intent[0] <= -0.5 * key);
  keys.set_pressed(DriveKey::LeftShift, shift);
  keys.set_pressed(DriveKey::Right, intent[1] >= 0.5 * steer_key);
  keys.set_pressed(DriveKey::Left, intent[1] <= -0.5 * steer_key);
  const input::DriveAction a = keys.action();
  return {a.accel, a.steer};
}

StepSequence with_keyboard_keys(StepSequence steps) {
  if (steps.action_dim < 2) return steps;
  std::vector<float>& a = steps.actions;
  for (std::size_t k = 0; k + 1 < a.size(); k += static_cast<std::size_t>(steps.action_dim)) {
    const ParkingAction keys = keyboard_keys({a[k], a[k + 1]});
    a[k] = static_cast<float>(keys[0]);
    a[k + 1] = static_cast<float>(keys[1]);
  }
  return steps;
}

ParkingTrial realistic_drive(const ParkingTrial& expert, const RealisticDriverProfile& p, Rng& rng) {
  check(expert, p);
  const DriveTiming t = drive_timing(expert, p);
  DriverIntent intent(expert, p, t);
  ParkingTrial out;
  out.scenario = expert.scenario;
  out.control_hz = p.control_hz;
  out.source = "learner";
  out.device = device_name(p.device);
  ParkingSim sim(expert.scenario);
  out.states.push_back(sim.observation());
  Wander wander(p.stick_noise, p.noise_time_constant_s, p.control_hz);
  wander.start(rng);
  std::array<ParkingAction, parking::kSubstepsPerAction> sub{};
  std::vector<VehicleState> seen;  // the car at the start of each input sample (for the follower)
  for (int k = 0; k < t.samples && !sim.done(); k += t.per_step) {
    double speed = sim.vehicle().speed;  // within the control step: v += 5 u0 / input rate (exact, no drag)
    VehicleState car = sim.vehicle();
    for (int s = 0; s < t.per_step; ++s) {
      if (intent.follows()) seen.push_back(car);
      const ParkingAction wanted = intent.at(k + s - t.delay - t.wait, seen, speed);
      const ParkingAction u = with_deficit(through_device(p, wanted, wander.next(rng)), p.deficit, speed, p.control_hz);
      speed += clip_action(u)[0] * parking::kMaxAcceleration / p.control_hz;
      for (int h = 0; intent.follows() && h < t.substeps_per_sample; ++h)  // where the driver will see the car next
        car = bicycle_substep(car, acceleration_of(clip_action(u)), steering_of(clip_action(u)));
      sub[static_cast<std::size_t>(s)] = u;
      out.actions.push_back(u);
    }
    const ParkingStepResult r = t.per_step == 1 ? sim.step(sub[0]) : sim.step_substeps(sub);
    out.states.push_back(sim.observation());
    out.rewards.push_back(r.reward);
  }
  out.success = sim.succeeded();
  return out;
}

}  // namespace sc
