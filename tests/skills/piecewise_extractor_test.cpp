#include "teaching/skills/piecewise_extractor.hpp"

#include <memory>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"

namespace sc {
namespace {

StepSequence steps(int length) {
  StepSequence s;
  s.state_dim = 1;
  s.action_dim = 1;
  for (int t = 0; t < length; ++t) {
    s.states.push_back(static_cast<float>(t));
    s.actions.push_back(static_cast<float>(t));
  }
  return s;
}

// Records the first state of every trajectory it reads, and reads each as one segment of skill 0.
class RecordingExtractor final : public SkillExtractor {
 public:
  Segmentation extract(const StepSequence& x) const override {
    firsts.push_back(x.states.empty() ? -1.0f : x.states.front());
    return x.length() > 0 ? Segmentation{{{0, 0, x.length()}}} : Segmentation{};
  }
  int num_skills() const override { return 1; }
  std::string name() const override { return "recording"; }
  mutable std::vector<float> firsts;
};

TEST(PiecewiseExtractor, CountsPiecesAsTheRoundedRatioOfLengths) {
  EXPECT_EQ(piece_count(10, 26), 1);
  EXPECT_EQ(piece_count(38, 26), 1);  // 38 / 26 = 1.46
  EXPECT_EQ(piece_count(39, 26), 2);  // 1.5: halves round up
  EXPECT_EQ(piece_count(64, 26), 2);  // 2.46
  EXPECT_EQ(piece_count(65, 26), 3);  // 2.5
  EXPECT_EQ(piece_count(0, 26), 1);
  EXPECT_EQ(piece_count(1, 26), 1);
  for (int piece : {1, 2, 25, 26}) {
    EXPECT_EQ(piece_count(shortest_split_length(piece), piece), 2) << piece;
    EXPECT_EQ(piece_count(shortest_split_length(piece) - 1, piece), 1) << piece;
  }
}

TEST(PiecewiseExtractor, ReadsATrajectoryAboutAsLongAsAPieceExactlyAsTheWrappedExtractor) {
  const auto inner = std::make_shared<TimeHeuristicExtractor>(4);
  const PiecewiseExtractor pieces(inner, 26);
  for (int length : {0, 1, 5, 26, 38}) {
    EXPECT_EQ(pieces.extract(steps(length)), inner->extract(steps(length))) << length;
    EXPECT_EQ(pieces.extract_all({steps(length)}).front(), inner->extract(steps(length))) << length;
  }
  EXPECT_EQ(pieces.name(), "time-heuristic");
  EXPECT_EQ(pieces.num_skills(), 4);
}

TEST(PiecewiseExtractor, ReadsALongTrajectoryInEqualConsecutivePiecesJoinedInPlace) {
  // 65 steps in pieces of about 26: three pieces [0, 21), [21, 43), [43, 65), each cut in two by the heuristic.
  const PiecewiseExtractor pieces(std::make_shared<TimeHeuristicExtractor>(2), 26);
  const Segmentation s = pieces.extract(steps(65));
  const Segmentation expected{{{0, 0, 11}, {1, 11, 21}, {0, 21, 32}, {1, 32, 43}, {0, 43, 54}, {1, 54, 65}}};
  EXPECT_EQ(s, expected);
}

TEST(PiecewiseExtractor, GivesEachPieceItsOwnStepsAllInOneBatch) {
  auto inner = std::make_shared<RecordingExtractor>();
  const PiecewiseExtractor pieces(inner, 10);
  const std::vector<Segmentation> read = pieces.extract_all({steps(30), steps(12)});
  EXPECT_EQ(inner->firsts, (std::vector<float>{0.0f, 10.0f, 20.0f, 0.0f}));
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0], (Segmentation{{{0, 0, 10}, {0, 10, 20}, {0, 20, 30}}}));
  EXPECT_EQ(read[1], (Segmentation{{{0, 0, 12}}}));
  EXPECT_EQ(pieces.extract(steps(30)), read[0]);
}

TEST(PiecewiseExtractor, RefusesNoExtractorAndEmptyPieces) {
  EXPECT_THROW(PiecewiseExtractor(nullptr, 10), InputError);
  EXPECT_THROW(PiecewiseExtractor(std::make_shared<TimeHeuristicExtractor>(2), 0), InputError);
}

}  // namespace
}  // namespace sc
