#include "teaching/tasks/parking_kit.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

std::filesystem::path scratch(const std::string& name) {
  const char* dir = std::getenv("SKILLCOACH_TEST_OUTPUT");
  std::filesystem::path p = std::filesystem::path(dir ? dir : ".") / "tasks" / name;
  std::filesystem::create_directories(p.parent_path());
  std::filesystem::remove(p);
  return p;
}

std::shared_ptr<const SkillExtractor> time_slices() { return std::make_shared<TimeHeuristicExtractor>(3); }

// Planning costs ~20-50 ms per scenario: one small pool shared by the tests of this file.
const ParkingKit& kit() {
  static const ParkingKit k(time_slices(), "", ParkingKitOptions{{}, ParkingPoolOptions{8, 3}, std::nullopt});
  return k;
}

TEST(ParkingKit, PoolIsSegmentedByTheExtractorAndTheTimeHeuristic) {
  ASSERT_EQ(kit().expert_pool().size(), 8u);
  for (const ExpertDemo& d : kit().expert_pool()) {
    EXPECT_EQ(d.steps.state_dim, 12);
    EXPECT_GT(d.steps.length(), 3);
    EXPECT_EQ(d.time_slices.segments.size(), 3u);  // K = 3
    EXPECT_EQ(d.skills, TimeHeuristicExtractor(3).extract(d.steps));
    EXPECT_LE(d.reward, 0.0);
    EXPECT_TRUE(is_success_reward(d.reward)) << d.reward;  // the expert parks
    EXPECT_EQ(d.trial.at("source"), "expert");
  }
}

TEST(ParkingKit, ReadsALearnersDriveFromItsFirstMovingStep) {
  // An expert drive after six steps of standing still, as a learner starts after the countdown.
  const StepSequence moving = kit().expert_pool()[0].steps;
  StepSequence late = moving;
  for (int i = 0; i < 6; ++i)
    late.states.insert(late.states.begin(), moving.states.begin(), moving.states.begin() + kParkingStateDim);
  late.actions.insert(late.actions.begin(), 6 * kParkingActionDim, 0.0f);
  ASSERT_EQ(late.length(), moving.length() + 6);
  Segmentation expected = TimeHeuristicExtractor(3).extract(moving);
  for (SkillSegment& s : expected.segments) s.begin += 6, s.end += 6;
  expected.segments.front().begin = 0;
  EXPECT_EQ(kit().extractor().extract(late), expected);
  EXPECT_NE(TimeHeuristicExtractor(3).extract(late), expected);  // read whole, the thirds fall elsewhere
}

TEST(ParkingKit, SameSeedSamePoolOtherSeedOtherPool) {
  const ParkingKit again(time_slices(), "", ParkingKitOptions{{}, ParkingPoolOptions{8, 3}, std::nullopt});
  const ParkingKit other(time_slices(), "", ParkingKitOptions{{}, ParkingPoolOptions{8, 4}, std::nullopt});
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(again.expert_pool()[i].trial, kit().expert_pool()[i].trial);
    EXPECT_NE(other.expert_pool()[i].scenario, kit().expert_pool()[i].scenario);
  }
}

TEST(ParkingKit, PoolFileIsWrittenThenReadBackAndRegeneratedWhenCorrupt) {
  const auto file = scratch("pool.json");
  const ParkingPoolOptions options{3, 11};
  const LoadedParkingPool first = load_or_generate_parking_pool(file, options);
  EXPECT_NE(first.notice.find("missing; regenerated and saved"), std::string::npos) << first.notice;
  ASSERT_TRUE(std::filesystem::exists(file));
  const LoadedParkingPool second = load_or_generate_parking_pool(file, options);
  EXPECT_EQ(second.notice, "");
  ASSERT_EQ(second.trials.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(parking_trial_to_json(second.trials[i]), parking_trial_to_json(first.trials[i]));
  // Another seed's file is not silently used.
  EXPECT_THROW(parse_parking_pool(read_json_file(file), "pool.json", ParkingPoolOptions{3, 12}), InputError);
  std::ofstream(file) << "{\"format\": ";
  const LoadedParkingPool third = load_or_generate_parking_pool(file, options);
  EXPECT_NE(third.notice.find("regenerated"), std::string::npos);
  EXPECT_EQ(parking_trial_to_json(third.trials[2]), parking_trial_to_json(first.trials[2]));
}

TEST(ParkingPool, ScenariosAreSeededAndStayInTheirRegion) {
  for (int i = 0; i < 20; ++i) {
    EXPECT_EQ(parking_pool_scenario(3, i, GoalRegion::WholeLot), parking_pool_scenario(3, i));
    const ParkingScenario corner = parking_pool_scenario(3, i, GoalRegion::StudyCorner);
    EXPECT_GE(corner.goal_spot, 12);
    EXPECT_LE(corner.goal_spot, 14);
    EXPECT_EQ(corner.heading0, parking_pool_scenario(3, i).heading0);  // only the goal's draw differs
  }
  EXPECT_NE(parking_pool_scenario(3, 0), parking_pool_scenario(4, 0));
}

TEST(ParkingPool, AFileOfTheOtherRegionIsNotUsed) {
  const auto file = scratch("corner_pool.json");
  const ParkingPoolOptions corner{2, 5, GoalRegion::StudyCorner};
  const LoadedParkingPool first = load_or_generate_parking_pool(file, corner);
  for (const ParkingTrial& t : first.trials) EXPECT_GE(t.scenario.goal_spot, 12);
  EXPECT_EQ(load_or_generate_parking_pool(file, corner).notice, "");
  try {
    parse_parking_pool(read_json_file(file), "corner_pool.json", ParkingPoolOptions{2, 5});
    FAIL() << "a study-corner pool was accepted as the whole lot's";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pool of the study-corner, whole-lot expected"), std::string::npos)
        << e.what();
  }
  // Files written before regions existed hold whole-lot pools.
  Json old = parking_pool_json(ParkingPoolOptions{1, 5}, generate_parking_pool(ParkingPoolOptions{1, 5}));
  old.erase("region");
  EXPECT_EQ(parse_parking_pool(old, "old.json", ParkingPoolOptions{1, 5}).size(), 1u);
  EXPECT_THROW(parse_parking_pool(old, "old.json", ParkingPoolOptions{1, 5, GoalRegion::StudyCorner}), InputError);
}

TEST(ParkingKit, AStudyCornerKitDrawsFreshScenariosInTheCorner) {
  const ParkingKit corner(time_slices(), "",
                          ParkingKitOptions{{}, ParkingPoolOptions{2, 3, GoalRegion::StudyCorner}, std::nullopt});
  EXPECT_EQ(corner.goal_region(), GoalRegion::StudyCorner);
  EXPECT_EQ(kit().goal_region(), GoalRegion::WholeLot);
  std::set<int> spots;
  for (const Json& s : corner.fresh_scenarios(12, 7, {})) spots.insert(s.at("goal").at("spot").get<int>());
  EXPECT_EQ(spots, (std::set<int>{12, 13, 14}));
}

TEST(ParkingKit, RewardIsTheLastStepRewardAndReSimulatedWhenAbsent) {
  const Json& expert = kit().expert_pool()[0].trial;
  const double recorded = expert.at("rewards").back().get<double>();
  EXPECT_EQ(kit().reward_of(expert), recorded);
  Json bare = expert;
  bare.erase("rewards");
  bare.erase("states");
  EXPECT_NEAR(kit().reward_of(bare), recorded, 1e-12);
  // A learner who does nothing stays where the episode started: a lower score, not parked.
  Json idle = bare;
  idle["actions"] = Json::array({Json::array({0.0, 0.0}), Json::array({0.0, 0.0})});
  EXPECT_LT(kit().reward_of(idle), recorded);
  EXPECT_FALSE(is_success_reward(kit().reward_of(idle)));
}

TEST(ParkingKit, FreshScenariosAreDeterministicDistinctAndExcludeTheGivenOnes) {
  const std::vector<Json> first = kit().fresh_scenarios(4, 99, {});
  ASSERT_EQ(first.size(), 4u);
  EXPECT_EQ(kit().fresh_scenarios(4, 99, {}), first);
  const std::vector<Json> exclude{first[0], first[2]};
  const std::vector<Json> fresh = kit().fresh_scenarios(4, 99, exclude);
  ASSERT_EQ(fresh.size(), 4u);
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    for (const Json& e : exclude) EXPECT_NE(fresh[i], e);
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(fresh[i], fresh[j]);
  }
  EXPECT_EQ(fresh[0], first[1]);
  EXPECT_EQ(fresh[1], first[3]);
}

TEST(ParkingKit, ExpertTrialComesFromThePoolOrThePlanner) {
  const ExpertDemo& d = kit().expert_pool()[5];
  EXPECT_EQ(kit().expert_trial(d.scenario), d.trial);
  const Json fresh = kit().fresh_scenarios(1, 1234, {})[0];
  const Json planned = kit().expert_trial(fresh);
  EXPECT_EQ(planned.at("scenario"), fresh);
  EXPECT_TRUE(is_success_reward(kit().reward_of(planned)));
}

TEST(ParkingKit, TimeLimitGrowsWithTheExpertsLengthUpToTheHorizon) {
  EXPECT_DOUBLE_EQ(kit().time_limit_seconds(0), 5.0);
  EXPECT_DOUBLE_EQ(kit().time_limit_seconds(17), 2 * 17 * 0.2 + 5.0);
  EXPECT_DOUBLE_EQ(kit().time_limit_seconds(1000), 20.0);
}

TEST(ParkingKit, SkillsSharingWordsAreToldApartByWhatDiffersMost) {
  ParkingSkillMotion slow_back{10, -1.0, -0.2, 0.0, 1.0}, fast_back{12, -4.0, -0.5, 0.0, 1.0};
  ParkingSkillMotion forward{8, 3.0, 0.5, 0.0, 0.0}, unused{};
  const auto words = describe_parking_motions({fast_back, unused, forward, slow_back, unused});
  EXPECT_EQ(words[0], "reversing straight, quickly");
  EXPECT_EQ(words[3], "reversing straight, slowly");
  EXPECT_EQ(words[2], "driving forward straight");
  EXPECT_EQ(words[1], "unused skill");
  EXPECT_EQ(words[4], "unused skill");
  const auto three = describe_parking_motions({fast_back, slow_back, {5, -2.0, -0.3, 0.0, 1.0}});
  EXPECT_EQ(three[1], "reversing straight, slowly");
  EXPECT_EQ(three[2], "reversing straight, at medium speed");
  EXPECT_EQ(three[0], "reversing straight, quickly");
  // Same speed, different lock: how sharp they turn.
  ParkingSkillMotion gentle{10, -2.0, -0.3, -0.3, 1.0}, sharp{10, -2.1, -0.3, -0.4, 1.0};
  gentle.mean_abs_steering = 0.3;
  sharp.mean_abs_steering = 0.9;
  const auto turns = describe_parking_motions({gentle, sharp});
  EXPECT_EQ(turns[0], "reversing while steering left, with a gentle turn");
  EXPECT_EQ(turns[1], "reversing while steering left, with a sharp turn");
  // Same speed and lock, different part of the drive.
  ParkingSkillMotion early = gentle, late = gentle;
  early.mean_progress = 0.1;
  late.mean_progress = 0.8;
  const auto parts = describe_parking_motions({late, early});
  EXPECT_EQ(parts[0], "reversing while steering left, late in the manoeuvre");
  EXPECT_EQ(parts[1], "reversing while steering left, early in the manoeuvre");
  // Five alike in one part of the drive (a model of one's own): slower and faster half, then how sharp.
  std::vector<ParkingSkillMotion> five(5, gentle);
  for (std::size_t k = 0; k < five.size(); ++k) {
    five[k].mean_speed = -1.0 - static_cast<double>(k);
    five[k].mean_abs_steering = 0.2 + 0.15 * static_cast<double>(k);
    five[k].mean_progress = 0.5;
  }
  const auto alike = describe_parking_motions(five);
  EXPECT_EQ(alike[0], "reversing while steering left, midway through the manoeuvre, slowly, with a gentle turn");
  EXPECT_EQ(alike[1], "reversing while steering left, midway through the manoeuvre, slowly, with a sharp turn");
  EXPECT_EQ(alike[2], "reversing while steering left, midway through the manoeuvre, quickly, with a gentle turn");
  EXPECT_EQ(alike[4], "reversing while steering left, midway through the manoeuvre, quickly, with a sharp turn");
  EXPECT_EQ(std::set<std::string>(alike.begin(), alike.end()).size(), alike.size());
  for (const auto& w : {words, three, turns, parts, alike})
    for (const std::string& text : w) {
      EXPECT_EQ(text.find("pace"), std::string::npos) << text;
      EXPECT_EQ(text.find('('), std::string::npos) << text;
    }
}

TEST(ParkingKit, SkillWordsComeFromWhatTheSegmentsDo) {
  ParkingSkillMotion reverse{10, -3.0, -0.8, -0.6, 1.0};
  EXPECT_EQ(describe_parking_motion(reverse), "reversing while steering left");
  ParkingSkillMotion forward{10, 4.0, -0.5, 0.05, 0.0};
  EXPECT_EQ(describe_parking_motion(forward), "driving forward straight, braking");
  // Near-zero mean steering from full lock one way and then the other is not "straight".
  ParkingSkillMotion both_ways{10, -3.0, -0.3, 0.02, 1.0};
  both_ways.sharp_fraction = 0.69;
  EXPECT_EQ(describe_parking_motion(both_ways), "reversing while steering hard left and right");
  both_ways.sharp_fraction = 0.2;
  EXPECT_EQ(describe_parking_motion(both_ways), "reversing straight");
  // Half of it forward, half reversing, the pedal against the mean motion: it stops and turns around.
  ParkingSkillMotion turn_around{10, 1.9, -0.9, 0.4, 0.47};
  EXPECT_EQ(describe_parking_motion(turn_around), "stopping from driving forward, then reversing while steering right");
  EXPECT_TRUE(motion_reverses(turn_around));
  EXPECT_TRUE(motion_brakes(turn_around));
  ParkingSkillMotion back_then_forward{10, -4.0, 0.97, -0.5, 0.54};
  EXPECT_EQ(describe_parking_motion(back_then_forward),
            "stopping from reversing, then driving forward while steering left");
  back_then_forward.reverse_fraction = 1.0;  // braking hard but never leaving reverse
  EXPECT_EQ(describe_parking_motion(back_then_forward), "reversing while steering left, braking");
  EXPECT_EQ(describe_parking_motion(ParkingSkillMotion{}), "unused skill");
  for (int m = 0; m < 3; ++m) EXPECT_NE(kit().describe_skill(m), "unused skill");
  EXPECT_EQ(kit().describe_skill(7), "unknown skill");
}

}  // namespace
}  // namespace sc
