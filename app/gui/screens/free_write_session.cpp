#include "app/gui/screens/free_write_session.hpp"

#include "engine/core/rng.hpp"
#include "engine/writing/word_generator.hpp"

namespace sc {
namespace {

// The seeded word number `n`: its own random stream, so skipping ahead or changing alphabet never shifts
// another word.
std::string generated_word(writing::AlphabetKind kind, std::uint64_t seed, int n) {
  Rng rng = Rng(seed).fork(static_cast<std::uint64_t>(n));
  if (kind == writing::AlphabetKind::Classic) return writing::generate_classic_words(1, rng).front();
  return writing::generate_balinese_word(rng);
}

}  // namespace

FreeWriteSession::FreeWriteSession(std::uint64_t seed) : seed_(seed), pen_(writing::PenRecorderRules{}) {
  next_generated_word(writing::AlphabetKind::Classic);
}

void FreeWriteSession::set_scenario(writing::WritingScenario scenario) {
  gold_ = writing::gold_trajectory(scenario);  // may throw: change nothing until it succeeded
  scenario_ = std::move(scenario);
  gold_points_ = gold_.points();
  result_.reset();
  restart_trial();
}

void FreeWriteSession::next_generated_word(writing::AlphabetKind kind) {
  set_scenario({generated_word(kind, seed_, generated_), kind, {}});
  ++generated_;
}

std::string FreeWriteSession::use_word(writing::AlphabetKind kind, const std::string& word) {
  if (std::string problem = writing::word_problem(kind, word); !problem.empty()) return problem;
  set_scenario({word, kind, {}});
  return {};
}

void FreeWriteSession::restart_trial() { pen_ = writing_view::CanvasPenInput(writing::pen_rules_for(gold_)); }

void FreeWriteSession::score(writing::TimedTrace trace, writing::TrialEnd end) {
  FreeWriteResult result;
  result.end = end;
  result.seconds = trace.times.empty() ? 0.0 : trace.times.back();
  const writing::TimedTrace filled = writing::infill_trace(trace);
  result.score = writing::score_writing(gold_points_, filled.points);
  result.trial.scenario = scenario_;
  result.trial.points = filled.points;
  result.trial.times = filled.times;
  result.trial.score = result.score.score;
  result.trial.source = "learner";
  result.trial.device = "mouse";
  result_ = std::move(result);
}

bool FreeWriteSession::finish_if_ended() {
  if (!pen_.ended()) return false;
  score(pen_.raw(), pen_.end_reason());
  restart_trial();
  return true;
}

void FreeWriteSession::write_scripted(const writing_view::ScriptedHand& hand) {
  writing::TimedTrace trace;
  trace.points = writing_view::scripted_learner_trace(gold_points_, hand);
  // A steady hand at the expert's pace: `stride` gold steps between samples.
  for (std::size_t i = 0; i < trace.points.size(); ++i)
    trace.times.push_back(static_cast<double>(i * hand.stride) / writing::kExpertStepsPerSecond);
  score(std::move(trace),
        writing::trial_ends_on_release(scenario_.alphabet) ? writing::TrialEnd::Released : writing::TrialEnd::Done);
}

std::vector<writing::TracePoint> FreeWriteSession::ink() const {
  if (pen_.started()) return pen_.raw().points;
  return result_ ? result_->trial.points : std::vector<writing::TracePoint>{};
}

const char* free_write_instructions(writing::AlphabetKind kind) {
  return kind == writing::AlphabetKind::Classic
             ? "Hold the button and trace the grey word in one stroke, from the arrow on the left. Release to finish."
             : "Trace the grey word stroke by stroke, lifting the pen between strokes. Press Done or Enter when "
               "finished.";
}

const char* trial_end_text(writing::TrialEnd end) {
  switch (end) {
    case writing::TrialEnd::NotEnded:
      return "not ended";
    case writing::TrialEnd::Released:
      return "pen released";
    case writing::TrialEnd::Done:
      return "done";
    case writing::TrialEnd::TimeLimit:
      return "time limit reached";
    case writing::TrialEnd::TooLong:
      return "trace too long";
  }
  return "";
}

}  // namespace sc
