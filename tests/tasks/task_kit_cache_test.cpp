// One kit per task and lot, built once; a stored session gets the kit of the lot it recorded.
#include "teaching/tasks/task_kit_cache.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/tasks/parking_kit.hpp"

namespace sc {
namespace {

records::SessionRow parking_session(const std::string& settings_json) {
  records::SessionRow row;
  row.id = 7;
  row.learner = "Ada";
  row.task = "parking";
  row.condition = "adaptive";
  row.settings_json = settings_json;
  return row;
}

TEST(TaskKitCache, AStoredSessionGetsTheKitOfItsLotBuiltOnce) {
  TaskKitCache cache;
  const TaskKit& corner = cache.kit_of(parking_session(R"({"goal_region":"study-corner"})"));
  const auto* parking = dynamic_cast<const ParkingKit*>(&corner);
  ASSERT_NE(parking, nullptr);
  EXPECT_EQ(parking->goal_region(), GoalRegion::StudyCorner);
  for (const ExpertDemo& d : corner.expert_pool()) EXPECT_GE(d.scenario.at("goal").at("spot").get<int>(), 12);
  EXPECT_EQ(&cache.kit("parking", GoalRegion::StudyCorner), &corner);
  // Sessions recorded before lots existed ran on the whole lot.
  const TaskKit& whole = cache.kit_of(parking_session("{}"));
  EXPECT_NE(&whole, &corner);
  EXPECT_EQ(dynamic_cast<const ParkingKit&>(whole).goal_region(), GoalRegion::WholeLot);
  EXPECT_THROW(cache.kit_of(parking_session(R"({"goal_region":"corner"})")), InputError);
}

}  // namespace
}  // namespace sc
