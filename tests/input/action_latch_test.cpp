#include "engine/input/action_latch.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "engine/core/rng.hpp"

namespace sc::input {
namespace {

// Stand-in for ParkingSim's sub-step: the kinematic bicycle of reference-facts §1.5, dt = 1/15 s.
struct CarState {
  double x = 0.0, y = 0.0, heading = 0.3, speed = 0.0;
};

CarState substep(CarState s, const DriveAction& u) {
  constexpr double dt = 1.0 / 15.0;
  const double accel = 5.0 * u.accel;
  const double delta = std::numbers::pi / 4.0 * u.steer;
  const double beta = std::atan(0.5 * std::tan(delta));
  s.x += s.speed * std::cos(s.heading + beta) * dt;
  s.y += s.speed * std::sin(s.heading + beta) * dt;
  s.heading += s.speed * std::sin(beta) / 2.5 * dt;
  s.speed += accel * dt;
  return s;
}

bool bit_identical(const CarState& a, const CarState& b) {
  return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
         std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
         std::bit_cast<std::uint64_t>(a.heading) == std::bit_cast<std::uint64_t>(b.heading) &&
         std::bit_cast<std::uint64_t>(a.speed) == std::bit_cast<std::uint64_t>(b.speed);
}

// A jittery human on a stick: a random walk plus per-sample noise, with the odd broken sample.
std::vector<DriveAction> noisy_input_stream(int substeps, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<DriveAction> out;
  DriveAction walk;
  for (int i = 0; i < substeps; ++i) {
    walk.accel = std::clamp(walk.accel + 0.2 * rng.normal(), -1.2, 1.2);
    walk.steer = std::clamp(walk.steer + 0.2 * rng.normal(), -1.2, 1.2);
    DriveAction sample{walk.accel + 0.05 * rng.normal(), walk.steer + 0.05 * rng.normal()};
    if (rng.below(40) == 0) sample.steer = std::numeric_limits<double>::quiet_NaN();
    out.push_back(sample);
  }
  return out;
}

// What a trajectory file stores: "actions": [[u0, u1], ...] and "action_substeps" when not 3.
nlohmann::json to_json(const RecordedActions& rec) {
  nlohmann::json actions = nlohmann::json::array();
  for (const DriveAction& a : rec.actions) actions.push_back({a.accel, a.steer});
  return {{"action_substeps", rec.substeps_per_action}, {"actions", actions}};
}

RecordedActions from_json(const nlohmann::json& doc) {
  RecordedActions rec;
  rec.substeps_per_action = doc.at("action_substeps").get<int>();
  for (const auto& a : doc.at("actions")) rec.actions.push_back({a.at(0).get<double>(), a.at(1).get<double>()});
  return rec;
}

TEST(ActionLatch, LatchedSamplesEveryThirdSubstepAndHolds) {
  ActionLatch latch(ActionTiming::Latched);
  EXPECT_EQ(latch.recorded().substeps_per_action, 3);
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(latch.samples_next(), k % 3 == 0) << k;
    const DriveAction live{0.1 * k, -0.05 * k};
    const DriveAction applied = latch.next_substep(live);
    const int sampled_at = k / 3 * 3;
    EXPECT_EQ(applied, (DriveAction{0.1 * sampled_at, -0.05 * sampled_at})) << k;
  }
  ASSERT_EQ(latch.recorded().actions.size(), 3u);  // sub-steps 0, 3, 6
  EXPECT_EQ(latch.recorded().actions[2], (DriveAction{0.1 * 6, -0.05 * 6}));
  EXPECT_EQ(latch.substeps_done(), 8);
}

TEST(ActionLatch, ResponsiveAppliesEverySample) {
  ActionLatch latch(ActionTiming::Responsive);
  EXPECT_EQ(latch.recorded().substeps_per_action, 1);
  for (int k = 0; k < 5; ++k) {
    const DriveAction live{0.1 * k, 0.2};
    EXPECT_EQ(latch.next_substep(live), live);
  }
  EXPECT_EQ(latch.recorded().actions.size(), 5u);
}

TEST(ActionLatch, RecordsAndAppliesTheSanitisedAction) {
  ActionLatch latch(ActionTiming::Responsive);
  const DriveAction applied = latch.next_substep({std::numeric_limits<double>::quiet_NaN(), 3.0});
  EXPECT_EQ(applied, (DriveAction{0.0, 1.0}));
  EXPECT_EQ(latch.recorded().actions.front(), applied);
}

TEST(RecordedActions, ActionForSubstepExpandsAndChecksBounds) {
  RecordedActions rec{3, {{0.1, 0.2}, {0.3, 0.4}}};
  EXPECT_EQ(rec.substep_count(), 6);
  EXPECT_EQ(rec.action_for_substep(2), (DriveAction{0.1, 0.2}));
  EXPECT_EQ(rec.action_for_substep(3), (DriveAction{0.3, 0.4}));
  EXPECT_THROW(rec.action_for_substep(6), std::out_of_range);
  EXPECT_THROW(rec.action_for_substep(-1), std::out_of_range);
}

class RecordedTrialReplay : public testing::TestWithParam<ActionTiming> {};

TEST_P(RecordedTrialReplay, ReplaysBitForBitThroughAFileRoundTrip) {
  const std::vector<DriveAction> stream = noisy_input_stream(301, 7);  // not a multiple of 3 on purpose
  ActionLatch latch(GetParam());
  std::vector<CarState> live_states;
  CarState car;
  for (const DriveAction& live : stream) {
    car = substep(car, latch.next_substep(live));
    live_states.push_back(car);
  }

  const RecordedActions replayed_from = from_json(nlohmann::json::parse(to_json(latch.recorded()).dump()));
  ASSERT_GE(replayed_from.substep_count(), static_cast<std::int64_t>(stream.size()));
  CarState again;
  for (std::size_t i = 0; i < live_states.size(); ++i) {
    again = substep(again, replayed_from.action_for_substep(static_cast<std::int64_t>(i)));
    ASSERT_TRUE(bit_identical(again, live_states[i])) << "sub-step " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(BothTimings, RecordedTrialReplay,
                         testing::Values(ActionTiming::Latched, ActionTiming::Responsive),
                         [](const testing::TestParamInfo<ActionTiming>& info) {
                           return info.param == ActionTiming::Latched ? "Latched" : "Responsive";
                         });

TEST(RecordedTrialReplay, TimingChangesTheTrajectorySoTheFlagMatters) {
  // Replaying a responsive recording as if it were latched must not reproduce the drive; this is why the
  // trial stores substeps_per_action.
  const std::vector<DriveAction> stream = noisy_input_stream(90, 11);
  ActionLatch responsive(ActionTiming::Responsive);
  CarState live;
  for (const DriveAction& u : stream) live = substep(live, responsive.next_substep(u));
  RecordedActions misread = responsive.recorded();
  misread.substeps_per_action = 3;
  CarState wrong;
  for (std::int64_t i = 0; i < 90; ++i) wrong = substep(wrong, misread.action_for_substep(i));
  EXPECT_GT(std::hypot(wrong.x - live.x, wrong.y - live.y), 0.1);
}

}  // namespace
}  // namespace sc::input
