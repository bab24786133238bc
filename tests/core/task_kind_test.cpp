#include "engine/core/task_kind.hpp"

#include <gtest/gtest.h>

#include <string>

#include "engine/core/error.hpp"

namespace sc {
namespace {

TEST(TaskKind, TextRoundTripsAndAnythingElseIsNamed) {
  for (TaskKind task : {TaskKind::parking, TaskKind::writing}) EXPECT_EQ(task_kind_of(to_string(task)), task);
  EXPECT_EQ(task_kind_of("Parking"), std::nullopt);
  EXPECT_EQ(task_kind_of(""), std::nullopt);
  try {
    parse_task_kind("juggling", "trial.json: $.task");
    FAIL() << "accepted an unknown task";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "trial.json: $.task: 'juggling' is not parking or writing");
  }
}

}  // namespace
}  // namespace sc
