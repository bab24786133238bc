#include "engine/parking/parking_expert.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>

#include "engine/parking/motion_primitive_search.hpp"

namespace sc {
namespace {

// CPU time of this thread in ms: "planning time on one core", unaffected by other processes sharing
// the machine (wall time would be, and the planner is single-threaded).
double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

Eigen::VectorXd to_vector(const std::vector<ParkingAction>& actions) {
  Eigen::VectorXd z(2 * actions.size());
  for (std::size_t t = 0; t < actions.size(); ++t) {
    z[2 * t] = actions[t][0];
    z[2 * t + 1] = actions[t][1];
  }
  return z;
}

std::vector<ParkingAction> to_actions(const Eigen::VectorXd& z) {
  std::vector<ParkingAction> out(z.size() / 2);
  for (std::size_t t = 0; t < out.size(); ++t) out[t] = {z[2 * t], z[2 * t + 1]};
  return out;
}

// The same manoeuvre over `steps` control steps: actions linearly interpolated in normalised time.
Eigen::VectorXd rescale(const Eigen::VectorXd& z, int steps) {
  const int old_steps = static_cast<int>(z.size() / 2);
  Eigen::VectorXd out(2 * steps);
  for (int t = 0; t < steps; ++t) {
    const double pos = steps == 1 ? 0.0 : static_cast<double>(t) * (old_steps - 1) / (steps - 1);
    const int i = std::min(static_cast<int>(pos), old_steps - 1);
    const int j = std::min(i + 1, old_steps - 1);
    const double f = pos - i;
    for (int c = 0; c < 2; ++c) out[2 * t + c] = (1 - f) * z[2 * i + c] + f * z[2 * j + c];
  }
  return out;
}

// The staging pose: on the spot's axis, 3 m of aisle in front of the entrance (car centre 7 m from the
// spot centre), oriented as the car must end (nose in, or nose out for reverse-in goals).
Pose staging_pose(const ParkingScenario& scenario) {
  const Pose spot = spot_pose(scenario.goal_spot);
  const double in_x = std::cos(spot.heading), in_y = std::sin(spot.heading);
  return {spot.x - 7.0 * in_x, spot.y - 7.0 * in_y, goal_pose(scenario).heading};
}

}  // namespace

// Better plan first: success without collision, then fewer steps, then higher return.
bool better_plan(const ParkingPlan& a, const ParkingPlan& b) {
  const bool ok_a = a.success && !a.collision, ok_b = b.success && !b.collision;
  if (ok_a != ok_b) return ok_a;
  if (ok_a && a.success_step != b.success_step) return a.success_step < b.success_step;
  if (!ok_a) return (a.rewards.empty() ? -1e9 : a.rewards.back()) > (b.rewards.empty() ? -1e9 : b.rewards.back());
  return a.total_return() > b.total_return();
}

double ParkingPlan::total_return() const {
  double sum = 0.0;
  for (double r : rewards) sum += r;
  return sum;
}

ParkingTrial ParkingPlan::to_trial(const ParkingScenario& scenario) const {
  ParkingTrial trial;
  trial.scenario = scenario;
  trial.actions = actions;
  trial.states = states;
  trial.rewards = rewards;
  trial.success = success;
  trial.source = "expert";
  return trial;
}

ParkingPlan simulate_plan(const ParkingScenario& scenario, const std::vector<ParkingAction>& actions) {
  ParkingSim sim(scenario);
  ParkingPlan plan;
  plan.states.push_back(sim.observation());
  for (const auto& a : actions) {
    if (sim.done()) break;
    const ParkingAction u = clip_action(a);
    const ParkingStepResult r = sim.step(u);
    plan.actions.push_back(u);
    plan.states.push_back(sim.observation());
    plan.rewards.push_back(r.reward);
    if (r.success) {
      plan.success = true;
      plan.success_step = sim.steps();
    }
    plan.collision = plan.collision || r.collision;
  }
  return plan;
}

ParkingExpert::ParkingExpert(ParkingExpertOptions options) : options_(options) {}

std::vector<ParkingExpert::Candidate> ParkingExpert::direct_candidates(const ParkingScenario& scenario,
                                                                       const CollisionChecker& collisions,
                                                                       ActionSequenceOptimizer& optimizer) const {
  std::vector<Candidate> out;
  for (const auto& guess :
       search_manoeuvres(scenario, collisions, goal_pose(scenario), options_.max_steps, options_.guesses)) {
    // Give the optimiser a couple of steps more than the primitive needed to come close.
    std::vector<ParkingAction> init = guess.actions;
    init.resize(std::min<std::size_t>(init.size() + 2, options_.max_steps), init.back());
    const OptimizedSequence opt = optimizer.optimize(to_vector(init), options_.first_iterations);
    out.push_back({opt.actions, simulate_plan(scenario, to_actions(opt.actions))});
  }
  return out;
}

std::vector<ParkingExpert::Candidate> ParkingExpert::staged_candidates(const ParkingScenario& scenario,
                                                                       const CollisionChecker& collisions,
                                                                       ActionSequenceOptimizer& optimizer) const {
  // Between parked cars the car must be straight before it enters: first reach the staging pose, then
  // roll straight in, then optimise the whole sequence for the goal.
  const Pose staging = staging_pose(scenario);
  std::vector<Candidate> out;
  for (const auto& guess :
       search_manoeuvres(scenario, collisions, staging, options_.max_steps, options_.staged_guesses)) {
    std::vector<ParkingAction> init = guess.actions;
    init.resize(std::min<std::size_t>(init.size() + 2, options_.max_steps), init.back());
    optimizer.set_target(staging, 0.5, scenario.reverse_in ? -options_.roll_in_speed : options_.roll_in_speed, 1.0);
    const OptimizedSequence reach = optimizer.optimize(to_vector(init), options_.first_iterations);
    std::vector<ParkingAction> full = to_actions(reach.actions);
    full.resize(std::min<std::size_t>(full.size() + options_.roll_in_steps, options_.max_steps),
                ParkingAction{0.0, 0.0});
    optimizer.set_target(goal_pose(scenario), options_.weights.depth_free, 0.0, options_.weights.arrival_speed_scale);
    const OptimizedSequence opt = optimizer.optimize(to_vector(full), options_.first_iterations);
    out.push_back({opt.actions, simulate_plan(scenario, to_actions(opt.actions))});
  }
  return out;
}

ParkingPlan ParkingExpert::shorten(const ParkingScenario& scenario, ActionSequenceOptimizer& optimizer,
                                   const Candidate& candidate) const {
  // Shrink the horizon while the simulator still reports a clean success.
  ParkingPlan shortest = candidate.plan;
  Eigen::VectorXd shortest_z = candidate.z.head(2 * shortest.success_step);
  for (int steps = shortest.success_step - 1; steps >= 1; --steps) {
    const OptimizedSequence opt = optimizer.optimize(rescale(shortest_z, steps), options_.shrink_iterations);
    ParkingPlan p = simulate_plan(scenario, to_actions(opt.actions));
    if (!p.success || p.collision) break;
    shortest = std::move(p);
    shortest_z = opt.actions.head(2 * shortest.success_step);
    steps = shortest.success_step;  // it may have succeeded even earlier
  }
  // A careful driver: allow a little more time so the arrival is slower and straighter.
  if (options_.careful_extra_steps > 0) {
    const int steps = shortest.success_step + options_.careful_extra_steps;
    const OptimizedSequence opt = optimizer.optimize(rescale(shortest_z, steps), options_.shrink_iterations);
    ParkingPlan p = simulate_plan(scenario, to_actions(opt.actions));
    if (p.success && !p.collision) shortest = std::move(p);
  }
  return shortest;
}

ParkingPlan ParkingExpert::plan(const ParkingScenario& scenario) const {
  const double started = thread_cpu_ms();
  const ParkingLayout layout = make_layout(scenario);
  const CollisionChecker collisions(layout);
  ActionSequenceOptimizer optimizer(scenario, layout, options_.weights);

  auto clean = [](const Candidate& c) { return c.plan.success && !c.plan.collision; };
  std::vector<Candidate> candidates = direct_candidates(scenario, collisions, optimizer);
  if (std::count_if(candidates.begin(), candidates.end(), clean) < options_.refine_best) {
    auto staged = staged_candidates(scenario, collisions, optimizer);
    candidates.insert(candidates.end(), std::make_move_iterator(staged.begin()), std::make_move_iterator(staged.end()));
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return better_plan(a.plan, b.plan); });

  ParkingPlan best = candidates.empty() ? simulate_plan(scenario, {}) : candidates.front().plan;
  const int refine = std::min<int>(options_.refine_best, static_cast<int>(candidates.size()));
  for (int c = 0; c < refine && clean(candidates[c]); ++c) {
    ParkingPlan shortest = shorten(scenario, optimizer, candidates[c]);
    if (better_plan(shortest, best)) best = std::move(shortest);
  }
  best.planning_ms = thread_cpu_ms() - started;
  return best;
}

}  // namespace sc
