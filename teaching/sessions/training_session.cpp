#include "teaching/sessions/training_session.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "engine/core/error.hpp"
#include "teaching/scenarios/diverse_scenario_selection.hpp"
#include "teaching/sessions/session_records.hpp"

namespace sc {
namespace {

const char* phase_words(SessionPhase phase) {
  switch (phase) {
    case SessionPhase::Pretest:
      return "the pre-test";
    case SessionPhase::Diagnosis:
      return "the diagnosis";
    case SessionPhase::Drills:
      return "the drills";
    case SessionPhase::Evaluation:
      return "the evaluation";
    case SessionPhase::Summary:
      return "the summary";
  }
  return "?";
}

// Calls the flow's screens should never make (work of another phase, a round that does not exist): a bug
// in the caller, not something to show a learner as an input problem.
[[noreturn]] void misuse(const std::string& what) { throw std::logic_error("training session: " + what); }

}  // namespace

TrainingSession::TrainingSession(const TaskKit& kit, records::RecordStore& store, TimestampSource now)
    : kit_(kit), store_(store), now_(std::move(now)) {}

TrainingSession::TrainingSession(const TaskKit& kit, records::RecordStore& store, SessionSettings settings,
                                 TimestampSource now)
    : TrainingSession(kit, store, std::move(now)) {
  settings.validate();
  settings_ = std::move(settings);
  select_pretest();
  const std::string started = now_();
  store_.ensure_learner(settings_.learner, started);
  session_id_ = store_.begin_session(session_record(settings_, kit_.task(), started));
  rounds_.resize(1);
}

void TrainingSession::select_pretest() {
  const auto& pool = kit_.expert_pool();
  if (pool.empty()) throw InputError(kit_.task() + " expert pool", "is empty: nothing to build a pre-test from");
  std::vector<Segmentation> skills;
  skills.reserve(pool.size());
  for (const ExpertDemo& demo : pool) skills.push_back(demo.skills);
  pretest_pool_ = select_diverse_scenarios(skills, settings_.pretest_count).scenarios();
}

std::vector<Json> TrainingSession::pretest_scenarios() const {
  std::vector<Json> out;
  for (int i : pretest_pool_) out.push_back(kit_.expert_pool()[static_cast<std::size_t>(i)].scenario);
  return out;
}

const std::vector<ExpertDemo>& TrainingSession::eval_experts() const {
  const int r = round();
  auto it = eval_experts_.find(r);
  if (it != eval_experts_.end()) return it->second;
  // Each round gets its own fresh scenarios (a forked seed), all different from the pre-test's.
  const std::uint64_t seed = Rng(settings_.seed).fork(static_cast<std::uint64_t>(r)).next_u64();
  std::vector<ExpertDemo> demos;
  for (Json& scenario : kit_.fresh_scenarios(settings_.eval_count, seed, pretest_scenarios())) {
    ExpertDemo demo;
    demo.trial = kit_.expert_trial(scenario);
    demo.scenario = std::move(scenario);
    demo.steps = kit_.steps_of(demo.trial);
    demo.skills = kit_.extractor().extract(demo.steps);
    demo.reward = kit_.reward_of(demo.trial);
    demos.push_back(std::move(demo));
  }
  if (static_cast<int>(demos.size()) != settings_.eval_count)
    throw InputError(kit_.task() + " task kit", "gave " + std::to_string(demos.size()) + " fresh scenarios, " +
                                                    std::to_string(settings_.eval_count) + " were asked for");
  return eval_experts_.emplace(r, std::move(demos)).first->second;
}

int TrainingSession::test_count() const {
  return phase() == SessionPhase::Pretest ? static_cast<int>(pretest_pool_.size()) : settings_.eval_count;
}

const ExpertDemo& TrainingSession::test_expert() const {
  const std::size_t item = static_cast<std::size_t>(item_index());
  if (phase() == SessionPhase::Pretest) return kit_.expert_pool()[static_cast<std::size_t>(pretest_pool_.at(item))];
  require_phase(SessionPhase::Evaluation, "a test scenario");
  return eval_experts().at(item);
}

const Json& TrainingSession::test_scenario() const { return test_expert().scenario; }

const Json& TrainingSession::test_expert_trial() const { return test_expert().trial; }

double TrainingSession::test_time_limit() const { return kit_.time_limit_seconds(test_expert().steps.length()); }

records::SessionProgress TrainingSession::after_test_trial() const {
  records::SessionProgress next = progress_;
  ++next.item_index;
  if (next.item_index >= test_count()) {
    next.phase = phase() == SessionPhase::Pretest ? SessionPhase::Diagnosis : SessionPhase::Summary;
    next.item_index = 0;
  }
  return next;
}

SubmittedTrial TrainingSession::submit_test_trial(const Json& trial, const TrialTimes& times) {
  if (phase() != SessionPhase::Pretest && phase() != SessionPhase::Evaluation)
    misuse(std::string("a test trial was submitted during ") + phase_words(phase()));
  const bool pretest = phase() == SessionPhase::Pretest;
  const double reward = kit_.reward_of(trial);
  const records::SessionProgress next = after_test_trial();
  SubmittedTrial result = store_trial(pretest ? records::TrialKind::Pretest : records::TrialKind::Eval, std::nullopt,
                                      trial, reward, times, next);
  if (pretest)
    pretest_trials_.push_back(trial);
  else
    state(round()).eval.push_back(trial);
  set_progress(next, false);
  return result;
}

CurriculumInputs TrainingSession::curriculum_inputs() const {
  CurriculumInputs inputs;
  for (const ExpertDemo& demo : kit_.expert_pool()) {
    inputs.expert_skills.push_back(demo.skills);
    inputs.expert_time_slices.push_back(demo.time_slices);
  }
  inputs.seed = settings_.seed;
  if (const PlacedDiagnosis* placed = pretest_places())
    inputs.pretest = placed->expertise.estimate;
  else if (!pretest_trials_.empty() || !rounds_.empty())
    inputs.pretest = diagnose_trials(kit_, pretest_test_trials());
  return inputs;
}

const PlacedDiagnosis* TrainingSession::pretest_places() const {
  return pretest_places_ && pretest_places_trials_ == pretest_trials_.size() ? &*pretest_places_ : nullptr;
}

std::vector<TestTrial> TrainingSession::pretest_test_trials() const {
  std::vector<TestTrial> trials;
  for (std::size_t i = 0; i < pretest_trials_.size(); ++i) {
    const int pool = pretest_pool_.at(i);
    const ExpertDemo& expert = kit_.expert_pool()[static_cast<std::size_t>(pool)];
    trials.push_back({pool, expert.skills, pretest_trials_[i], expert.steps});
  }
  return trials;
}

CurriculumConfig TrainingSession::curriculum_config() const {
  CurriculumConfig config = kit_.curriculum_config();
  config.weak_skills = settings_.weak_skills;
  config.drills_per_weak_skill = settings_.drills_per_weak_skill;
  return config;
}

void TrainingSession::compute_round(int r) {
  // An Adaptive round builds on every earlier one (resume may reach here before they were recomputed).
  if (r > 1 && !state(r - 1).analysed) compute_round(r - 1);
  RoundState& st = state(r);
  if (!pretest_trials_.empty() && !pretest_places()) {
    pretest_places_ = diagnosis_with_places(kit_, pretest_test_trials());
    pretest_places_trials_ = pretest_trials_.size();
  }
  const CurriculumInputs inputs = curriculum_inputs();
  const CurriculumConfig config = curriculum_config();
  if (settings_.condition != StudyCondition::Adaptive) {
    st.diagnosis = inputs.pretest;
    st.curriculum = make_curriculum(settings_.condition, inputs, config);
  } else if (r == 1) {
    adaptive_rounds_.assign(1, first_adaptive_round(inputs, config));
  } else {
    // The learner's practice of the previous round is the new evidence (Alg. 2 against each drill's plan).
    const RoundState& last = state(r - 1);
    std::vector<ExpertiseTrial> evidence;
    for (const auto& [item, trial] : last.practice) {
      const PracticeItem& practice_item = last.curriculum.items.at(static_cast<std::size_t>(item));
      const PlayableDrill played = kit_.projector().project(practice_item.material);
      evidence.push_back(practice_trial(practice_item, kit_.extractor().extract(kit_.steps_of(trial)),
                                        kit_.drill_attempt_reward(played, trial), item));
    }
    adaptive_rounds_.resize(static_cast<std::size_t>(r - 1));
    adaptive_rounds_.push_back(next_round(adaptive_rounds_, evidence, inputs, config));
  }
  if (settings_.condition == StudyCondition::Adaptive) {
    st.diagnosis = adaptive_rounds_.back().diagnosis;
    st.curriculum = adaptive_rounds_.back().practice;
  }
  st.analysed = true;
}

void TrainingSession::analyse() {
  require_phase(SessionPhase::Diagnosis, "the analysis");
  const auto start = std::chrono::steady_clock::now();
  compute_round(round());
  analysis_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const RoundState& st = state(round());
  const std::string created = now_();
  store_.save_diagnosis(diagnosis_record(session_id_, round(), st.diagnosis, kit_.extractor().name(), created));
  store_.save_curriculum(curriculum_record(session_id_, round(), settings_.condition, st.curriculum, created));
  records::SessionProgress next{round(), SessionPhase::Drills, 0};
  if (practice_slot_count() == 0) next.phase = SessionPhase::Evaluation;
  set_progress(next, true);
}

const ExpertiseEstimate& TrainingSession::diagnosis() const {
  const RoundState& st = state(round());
  if (!st.analysed) misuse("the diagnosis is not made yet");
  return st.diagnosis;
}

const Curriculum& TrainingSession::curriculum() const {
  const RoundState& st = state(round());
  if (!st.analysed) misuse("the curriculum is not made yet");
  return st.curriculum;
}

std::vector<int> TrainingSession::slot_items(const Curriculum& curriculum) const {
  std::vector<int> items;
  for (std::size_t i = 0; i < curriculum.items.size(); ++i)
    for (int s = 0; s < curriculum.items[i].sessions; ++s) items.push_back(static_cast<int>(i));
  return items;
}

int TrainingSession::practice_slot_count() const { return static_cast<int>(slot_items(curriculum()).size()); }

int TrainingSession::practice_minutes() const {
  double seconds = 0.0;
  for (int item : slot_items(curriculum())) seconds += drill_time_limit(item);
  return static_cast<int>(std::ceil(seconds / 60.0));
}

int TrainingSession::current_item() const {
  require_phase(SessionPhase::Drills, "a practice item");
  return slot_items(curriculum()).at(static_cast<std::size_t>(item_index()));
}

int TrainingSession::session_of_slot() const {
  const std::vector<int> items = slot_items(curriculum());
  const int item = current_item();
  int n = 0;
  for (int i = 0; i <= item_index(); ++i) n += items[static_cast<std::size_t>(i)] == item ? 1 : 0;
  return n;
}

const PlayableDrill& TrainingSession::drill(int item) const {
  const auto key = std::make_pair(round(), item);
  auto it = drills_.find(key);
  if (it == drills_.end())
    it = drills_.emplace(key, kit_.projector().project(curriculum().items.at(static_cast<std::size_t>(item)).material))
             .first;
  return it->second;
}

double TrainingSession::drill_time_limit(int item) const { return kit_.time_limit_seconds(drill(item).steps.length()); }

records::SaveResult TrainingSession::record_demo(int item, const Json& expert_trial, const TrialTimes& times) {
  require_phase(SessionPhase::Drills, "a demo");
  return store_trial(records::TrialKind::Demo, item, expert_trial, std::nullopt, times, std::nullopt).saved;
}

records::SessionProgress TrainingSession::after_practice_slot() const {
  records::SessionProgress next = progress_;
  ++next.item_index;
  if (next.item_index >= practice_slot_count()) next = {round(), SessionPhase::Evaluation, 0};
  return next;
}

SubmittedTrial TrainingSession::submit_practice(const Json& trial, const TrialTimes& times) {
  const int item = current_item();
  const records::SessionProgress next = after_practice_slot();
  const double reward = kit_.drill_attempt_reward(drill(item), trial);
  SubmittedTrial result = store_trial(records::TrialKind::Practice, item, trial, reward, times, next);
  state(round()).practice.emplace_back(item, trial);
  set_progress(next, false);
  return result;
}

SubmittedTrial TrainingSession::submit_extra_practice(int item, const Json& trial, const TrialTimes& times) {
  if (phase() != SessionPhase::Drills && phase() != SessionPhase::Evaluation)
    misuse(std::string("an extra practice trial during ") + phase_words(phase()));
  if (item < 0 || item >= static_cast<int>(curriculum().items.size()))
    misuse("practice item " + std::to_string(item) + " does not exist");
  const double reward = kit_.drill_attempt_reward(drill(item), trial);
  SubmittedTrial result = store_trial(records::TrialKind::Practice, item, trial, reward, times, progress_);
  state(round()).practice.emplace_back(item, trial);
  return result;
}

void TrainingSession::skip_practice() {
  require_phase(SessionPhase::Drills, "skipping practice");
  set_progress({round(), SessionPhase::Evaluation, 0}, true);
}

RoundSummary TrainingSession::summary() const {
  require_phase(SessionPhase::Summary, "the summary");
  std::vector<double> pre, eval;
  std::vector<TestTrial> eval_trials_list;
  for (const Json& trial : pretest_trials_) pre.push_back(kit_.reward_of(trial));
  const RoundState& st = state(round());
  const auto& experts = eval_experts();
  for (std::size_t i = 0; i < st.eval.size(); ++i) {
    eval.push_back(kit_.reward_of(st.eval[i]));
    eval_trials_list.push_back({static_cast<int>(i), experts.at(i).skills, st.eval[i], experts.at(i).steps});
  }
  // The pre-test's diagnosis as the analysis computed it (the same estimate), not a second time.
  const PlacedDiagnosis* placed = pretest_places();
  const ExpertiseEstimate before = placed ? placed->expertise.estimate : diagnose_trials(kit_, pretest_test_trials());
  return summarize_round(round(), pre, eval, before, diagnose_trials(kit_, eval_trials_list), practice_per_skill(),
                         static_cast<int>(st.practice.size()));
}

std::map<int, int> TrainingSession::practice_per_skill() const {
  const RoundState& st = state(round());
  std::vector<int> played;
  for (const auto& [item, trial] : st.practice) played.push_back(item);
  return practice_trials_per_skill(st.curriculum, played);
}

void TrainingSession::start_next_round() {
  require_phase(SessionPhase::Summary, "another round");
  if (!can_continue()) misuse("another round is offered in the Adaptive condition only");
  rounds_.resize(static_cast<std::size_t>(round()) + 1);
  set_progress({round() + 1, SessionPhase::Diagnosis, 0}, true);
}

void TrainingSession::finish() {
  if (finished_) return;
  store_.finish_session(session_id_, now_());
  finished_ = true;
}

const std::vector<Json>& TrainingSession::eval_trials(int r) const { return state(r).eval; }

TrainingSession::RoundState& TrainingSession::state(int r) {
  if (r < 1) misuse("round " + std::to_string(r) + " does not exist");
  if (static_cast<int>(rounds_.size()) < r) rounds_.resize(static_cast<std::size_t>(r));
  return rounds_[static_cast<std::size_t>(r - 1)];
}

const TrainingSession::RoundState& TrainingSession::state(int r) const {
  if (r < 1 || r > static_cast<int>(rounds_.size())) misuse("round " + std::to_string(r) + " has not started");
  return rounds_[static_cast<std::size_t>(r - 1)];
}

SubmittedTrial TrainingSession::store_trial(records::TrialKind kind, std::optional<int> drill, const Json& trial,
                                            std::optional<double> score, const TrialTimes& times,
                                            std::optional<records::SessionProgress> after) {
  records::TrialRecord record =
      trial_record({session_id_, kind, round(), drill}, kit_.task(), settings_.device, trial, score);
  record.started = times.started.empty() ? now_() : times.started;
  record.finished = times.finished.empty() ? now_() : times.finished;
  record.progress_after = after;
  SubmittedTrial result;
  result.reward = score.value_or(0.0);
  result.saved = store_.record_trial(record);
  return result;
}

void TrainingSession::set_progress(records::SessionProgress progress, bool save) {
  progress_ = progress;
  if (save) store_.save_progress(session_id_, progress_);
}

void TrainingSession::require_phase(SessionPhase phase, const char* what) const {
  if (progress_.phase != phase)
    misuse(std::string(what) + " belongs to " + phase_words(phase) + ", the session is at " +
           phase_words(progress_.phase));
}

}  // namespace sc
