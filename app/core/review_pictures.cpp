#include "app/core/review_pictures.hpp"

#include <algorithm>
#include <cstdio>
#include <set>

namespace sc {
namespace {

const review::TrialReview* find_trial(const std::vector<review::TrialReview>& trials, int seq) {
  for (const auto& t : trials)
    if (t.stored.seq == seq) return &t;
  return nullptr;
}

std::string score_text(double v) {
  char text[48];
  std::snprintf(text, sizeof text, "%.2f", v);
  return text;
}

double mean_reward(const std::vector<int>& seqs, const std::vector<review::TrialReview>& trials) {
  double sum = 0.0;
  int n = 0;
  for (int seq : seqs)
    if (const auto* t = find_trial(trials, seq)) {
      sum += t->reward;
      ++n;
    }
  return n ? sum / n : 0.0;
}

}  // namespace

review_view::ReviewPath review_path(const review::TrialTrack& track, const std::vector<review::SkillSpan>& spans) {
  review_view::ReviewPath path;
  for (const auto& p : track.points) path.points.push_back({static_cast<float>(p.x), static_cast<float>(p.y)});
  for (double h : track.headings) path.headings.push_back(static_cast<float>(h));
  for (const auto& s : spans) path.spans.push_back({s.skill, s.begin, s.end});
  return path;
}

review_view::SkillPalette session_palette(const review::ExpertiseRounds& rounds) {
  std::vector<int> skills;
  for (const auto& s : rounds.skills) skills.push_back(s.skill);
  return review_view::SkillPalette(std::move(skills));
}

review_view::TrialPicture trial_picture(const review::TrialReview& trial, const review_view::SkillPalette& palette) {
  review_view::TrialPicture picture;
  picture.palette = palette;
  picture.task = trial.task;
  picture.scenario = trial.learner.at("scenario");
  picture.learner = review_path(trial.learner_track, trial.learner_skills);
  if (trial.expert) picture.expert = review_path(trial.expert_track, trial.expert_skills);
  if (trial.ghost) picture.ghost = review_path(trial.ghost_track, trial.ghost_skills);
  return picture;
}

review_view::RewardPlot reward_plot(const review::TrialReview& trial) {
  review_view::RewardPlot plot;
  plot.times = trial.reward_times;
  plot.rewards = trial.rewards;
  plot.caption =
      trial.task == TaskKind::parking ? "reward per control step (0 = goal)" : "score of the ink so far (0 = perfect)";
  return plot;
}

review_view::TrialImageText trial_image_text(const std::string& learner, const review::TrialReview& trial) {
  review_view::TrialImageText text;
  text.title = learner + " - " + std::string(to_string(trial.task)) + " - " + trial.label;
  const auto& r = trial.stored.record;
  text.lines.push_back(
      (r.score ? "score " + score_text(*r.score) : "demo (not scored), reward " + score_text(trial.reward)) + ", " +
      std::to_string(trial.learner_track.steps()) + " steps, " + r.device);
  std::set<int> seen;
  for (const auto* spans : {&trial.learner_skills, &trial.expert_skills, &trial.ghost_skills})
    for (const auto& s : *spans)
      if (seen.insert(s.skill).second) text.legend.push_back({s.skill, s.description});
  std::sort(text.legend.begin(), text.legend.end(), [](const auto& a, const auto& b) { return a.skill < b.skill; });
  text.plot = reward_plot(trial);
  return text;
}

review_view::ExpertiseChart expertise_chart(const review::ExpertiseRounds& rounds,
                                            const review_view::SkillPalette& palette) {
  review_view::ExpertiseChart chart;
  chart.palette = palette;
  for (int r : rounds.rounds) chart.rounds.push_back("round " + std::to_string(r));
  for (const auto& s : rounds.skills) chart.skills.push_back({s.skill, s.description, s.expertise, s.drilled});
  chart.lowest = rounds.lowest;
  return chart;
}

review_view::BeforeAfterPicture before_after_picture(const review::BeforeAfterGroup& group,
                                                     const std::vector<review::TrialReview>& trials) {
  review_view::BeforeAfterPicture picture;
  auto add = [&](const std::vector<int>& seqs, std::vector<std::vector<Vec2f>>& into) {
    for (int seq : seqs)
      if (const auto* t = find_trial(trials, seq)) {
        picture.task = t->task;
        picture.scenarios.push_back(t->learner.at("scenario"));
        into.push_back(review_path(t->learner_track, {}).points);
        if (t->expert) picture.experts.push_back(review_path(t->expert_track, {}).points);
      }
  };
  add(group.pretest_seqs, picture.before);
  add(group.eval_seqs, picture.after);
  return picture;
}

std::vector<std::string> before_after_lines(const review::BeforeAfterGroup& group,
                                            const std::vector<review::TrialReview>& trials) {
  std::vector<std::string> lines;
  if (!group.pretest_seqs.empty())
    lines.push_back("pre-test mean score " + score_text(mean_reward(group.pretest_seqs, trials)));
  if (!group.eval_seqs.empty())
    lines.push_back("evaluation mean score " + score_text(mean_reward(group.eval_seqs, trials)));
  lines.push_back("faint ribbons: the expert's paths of the same scenarios");
  return lines;
}

review_view::HandOverlay hand_overlay(const LearnerHandTraces& traces) {
  const auto points = [](const std::vector<std::pair<double, double>>& xy) {
    std::vector<ImVec2> out;
    for (const auto& [x, y] : xy) out.emplace_back(static_cast<float>(x), static_cast<float>(y));
    return out;
  };
  return {points(traces.learner), points(traces.guide), points(traces.hand)};
}

review_view::HandImageText hand_image_text(const std::string& learner, const std::string& hand) {
  return {learner + "'s own hand",
          {"Quality-aware expertise took " + hand +
           " as this learner's hand: each part of the pre-test was scored against the guide and against that hand, "
           "and only what is far from both counted as an error."},
          "The first pre-test word over the guide",
          "The same word over " + hand};
}

}  // namespace sc
