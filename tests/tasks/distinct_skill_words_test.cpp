#include "teaching/tasks/distinct_skill_words.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

TEST(DistinctSkillWords, OnlyUsedSkillsThatShareWordsAreRenamedInTheGivenOrder) {
  const std::vector<double> key = {3.0, 1.0, 2.0, 0.0};
  const auto words = distinct_skill_words(
      {"x", "x", "y", "x"}, {true, true, true, false}, [&](std::size_t a, std::size_t b) { return key[a] < key[b]; },
      [](const std::string& text, std::size_t k, std::size_t n) {
        return text + " " + std::to_string(k + 1) + "/" + std::to_string(n);
      });
  EXPECT_EQ(words, (std::vector<std::string>{"x 2/2", "x 1/2", "y", "x"}));
}

}  // namespace
}  // namespace sc
