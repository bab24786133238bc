#include "engine/parking/motion_primitive_search.hpp"

#include <algorithm>
#include <map>
#include <tuple>

#include "engine/parking/parking_sim.hpp"

namespace sc {
namespace {

constexpr double kThrottle = 0.7;
constexpr double kSteerings[] = {-1.0, -0.5, 0.0, 0.5, 1.0};
constexpr int kFirstPhaseSteps[] = {0, 2, 4, 6};

struct Walker {
  VehicleState state;
  bool crashed = false;
  void step(const ParkingAction& u, const CollisionChecker& collisions) {
    for (int k = 0; k < parking::kSubstepsPerAction && !crashed; ++k) {
      state = bicycle_substep(state, acceleration_of(u), steering_of(u));
      crashed = collisions.has_obstacles() && collisions.car_collides(state);
    }
  }
};

int sign(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

}  // namespace

std::vector<ManoeuvreGuess> search_manoeuvres(const ParkingScenario& scenario, const CollisionChecker& collisions,
                                              const Pose& target, int max_steps, int keep) {
  // Best guess per manoeuvre class (first direction, first turn side, second direction).
  std::map<std::tuple<int, int, int>, ManoeuvreGuess> best;
  for (int d1 : {1, -1}) {
    for (double s1 : kSteerings) {
      for (int k1 : kFirstPhaseSteps) {
        if (k1 == 0 && (d1 < 0 || s1 != 0.0)) continue;  // one "no first phase" entry
        Walker prefix{initial_vehicle_state(scenario)};
        const ParkingAction first{d1 * kThrottle, s1};
        for (int t = 0; t < k1 && !prefix.crashed; ++t) prefix.step(first, collisions);
        if (prefix.crashed) continue;
        for (int d2 : {1, -1}) {
          for (double s2 : kSteerings) {
            Walker walker = prefix;
            const ParkingAction second{d2 * kThrottle, s2};
            double best_score = 1e9;
            int best_step = 0;
            for (int t = k1; t < max_steps; ++t) {
              walker.step(second, collisions);
              if (walker.crashed) break;
              const double score = parking_goal_distance(make_observation(walker.state, target));
              if (score < best_score) {
                best_score = score;
                best_step = t + 1;
              }
            }
            if (best_step == 0) continue;
            const auto key = std::make_tuple(k1 == 0 ? d2 : d1, k1 == 0 ? sign(s2) : sign(s1), d2);
            auto it = best.find(key);
            if (it != best.end() && it->second.score <= best_score) continue;
            ManoeuvreGuess guess;
            guess.score = best_score;
            guess.actions.assign(k1, first);
            guess.actions.resize(best_step, second);
            best[key] = std::move(guess);
          }
        }
      }
    }
  }
  std::vector<ManoeuvreGuess> out;
  for (auto& [key, guess] : best) out.push_back(std::move(guess));
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.score < b.score; });
  if (static_cast<int>(out.size()) > keep) out.resize(keep);
  return out;
}

}  // namespace sc
