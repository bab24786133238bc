#include "app/gui/screens/free_drive_scenario.hpp"

#include <cmath>
#include <cstdio>

#include "engine/core/rng.hpp"

namespace sc {

ParkingScenario make_free_drive_scenario(const FreeDriveScenarioChoice& choice) {
  Rng rng(choice.seed);
  ParkingScenario scenario = sample_parking_scenario(rng, choice.variant, choice.reverse_in ? 1.0 : 0.0);
  if (choice.goal_spot >= 0 && choice.goal_spot < parking::kSpotCount) scenario.goal_spot = choice.goal_spot;
  return scenario;
}

std::string describe_spot(int spot) {
  const Pose p = spot_pose(spot);
  // Spots 0..14 lie at y = +14: below the start on the y-down screen.
  const char* row = p.y > 0 ? "lower row" : "upper row";
  const double dx = p.x;
  char text[96];
  if (std::fabs(dx) < 1e-9)
    std::snprintf(text, sizeof text, "spot %d: %s, straight %s", spot, row, p.y > 0 ? "down" : "up");
  else
    std::snprintf(text, sizeof text, "spot %d: %s, %.0f m %s", spot, row, std::fabs(dx), dx < 0 ? "left" : "right");
  return text;
}

}  // namespace sc
