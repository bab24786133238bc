#include "teaching/skills/phase_vote.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

TEST(PhaseVote, PhasesThatAgreeGiveTheirSegmentation) {
  const Segmentation one{{{2, 0, 40}, {5, 40, 90}, {2, 90, 120}}};
  EXPECT_EQ(vote_phases({one, one, one}, 120, 8), one);
}

TEST(PhaseVote, ABoundaryOnlyOnePhaseSeesIsDropped) {
  const Segmentation plain{{{2, 0, 60}, {5, 60, 120}}};
  const Segmentation extra{{{2, 0, 30}, {7, 30, 60}, {5, 60, 120}}};
  // Phase 2's extra cut at 30 has one vote of three; its actions 30..60 are outvoted by skill 2 too.
  EXPECT_EQ(vote_phases({plain, extra, plain}, 120, 8), plain);
}

TEST(PhaseVote, ABoundaryTheMajoritySeesIsKeptWhereThePhasesAgreeBest) {
  const Segmentation a{{{1, 0, 50}, {3, 50, 100}}};
  const Segmentation b{{{1, 0, 55}, {3, 55, 100}}};
  const Segmentation c{{{1, 0, 57}, {3, 57, 100}}};
  // All three positions have support 3; 55 is nearest the other two (spread 7, against 12 and 9).
  EXPECT_EQ(vote_phases({a, b, c}, 100, 8), (Segmentation{{{1, 0, 55}, {3, 55, 100}}}));
  // Out of each other's reach the three cuts have one vote each: no boundary survives.
  EXPECT_EQ(vote_phases({a, b, c}, 100, 1), (Segmentation{{{1, 0, 100}}}));
}

TEST(PhaseVote, NeighboursOfOneSkillStayApartWhenTheMajorityCutsThem) {
  const Segmentation cut{{{4, 0, 30}, {4, 30, 80}}};
  const Segmentation whole{{{4, 0, 80}}};
  EXPECT_EQ(vote_phases({cut, cut, whole}, 80, 8), cut);
  EXPECT_EQ(vote_phases({cut, whole, whole}, 80, 8), whole);
}

TEST(PhaseVote, EachSegmentTakesTheSkillMostOfItsActionsGetAndTiesGoToTheLowestId) {
  const Segmentation a{{{6, 0, 100}}};
  const Segmentation b{{{2, 0, 100}}};
  const Segmentation c{{{6, 0, 20}, {2, 20, 100}}};
  EXPECT_EQ(vote_phases({a, b, c}, 100, 8), (Segmentation{{{2, 0, 100}}}));  // 2: 180 actions, 6: 120
  EXPECT_EQ(vote_phases({a, b}, 100, 8), (Segmentation{{{2, 0, 100}}}));     // 100 each
}

TEST(PhaseVote, TheToleranceIsOneModelStepInActionsRoundedUp) {
  EXPECT_EQ(phase_vote_tolerance(1000, 125), 8);
  EXPECT_EQ(phase_vote_tolerance(1001, 125), 9);
  EXPECT_EQ(phase_vote_tolerance(3, 10), 1);
  EXPECT_EQ(phase_vote_tolerance(5, 0), 1);
}

}  // namespace
}  // namespace sc
