// TrainingSummary's JSON form (the model sidecar's "metrics"); no torch here.
#include <cmath>

#include "teaching/skills/compile_trainer.hpp"

namespace sc {

Json TrainingSummary::to_json() const {
  auto num = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  auto nums = [&](const std::vector<double>& values) {
    Json out = Json::array();
    for (double v : values) out.push_back(num(v));
    return out;
  };
  Json out{{"restart", restart},
           {"restart_valid_nll", nums(restart_valid_nll)},
           {"restart_unit_term", nums(restart_unit_term)},
           {"iterations_run", iterations_run},
           {"best_iteration", best_iteration},
           {"best_valid_nll", num(best_valid_nll)},
           {"final_loss", num(final_loss)},
           {"seconds", seconds},
           {"stopped_early", stopped_early},
           {"warm_start_boundaries", num(warm_start_boundaries)},
           {"warm_start_valid_nll", num(warm_start_valid_nll)},
           {"warm_start_unit_term", num(warm_start_unit_term)}};
  // Only with a review, so models trained without one keep their sidecars byte for byte.
  if (!restart_score.empty()) out["restart_score"] = nums(restart_score);
  return out;
}

}  // namespace sc
