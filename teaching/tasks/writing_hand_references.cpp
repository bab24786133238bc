#include "teaching/tasks/writing_hand_references.hpp"

#include <algorithm>

#include "teaching/tasks/writing_execution.hpp"
#include "teaching/tasks/writing_other_hand.hpp"
#include "teaching/tasks/writing_steps.hpp"

namespace sc {
namespace {

// Dynamic time warping on every 8th infilled step (8 px of pen path or less): the alignment only says which
// part of the reference does an expert segment, and the full 1 px steps cost 64 times as much (~0.2 s a drawer
// for a four-letter word).
constexpr int kAlignStride = 8;

// `word` moved onto the expert's first point (its size is the drawer's, as a learner writing in that hand has).
WrittenWord onto_expert_start(WrittenWord word, const TracePoint3& expert_start) {
  const double dx = expert_start[0] - word.points.front().x, dy = expert_start[1] - word.points.front().y;
  for (writing::TracePoint& p : word.points) p.x += dx, p.y += dy;
  return word;
}

// Steps 0, kAlignStride, 2 kAlignStride, ... of `steps`.
StepSequence every_nth_step(const StepSequence& steps) {
  StepSequence out{steps.state_dim, steps.action_dim, {}, {}};
  const auto copy_row = [](const std::vector<float>& from, std::vector<float>& to, int t, int dim) {
    const auto begin = from.begin() + static_cast<std::ptrdiff_t>(t) * dim;
    to.insert(to.end(), begin, begin + dim);
  };
  for (int t = 0; t < steps.length(); t += kAlignStride) {
    copy_row(steps.states, out.states, t, steps.state_dim);
    copy_row(steps.actions, out.actions, t, steps.action_dim);
  }
  return out;
}

// align_same_word on every kAlignStride-th step of both, spread back over the steps (spread_strided).
StepAlignment coarse_same_word(const StepSequence& expert, const StepSequence& reference) {
  return spread_strided(align_same_word(every_nth_step(expert), every_nth_step(reference)), kAlignStride,
                        expert.length(), reference.length());
}

}  // namespace

WritingHandReferences::WritingHandReferences(std::filesystem::path data_dir) : data_dir_(std::move(data_dir)) {}

std::vector<ExecutionReference> WritingHandReferences::references(const std::string& word,
                                                                  const StepSequence& expert) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (const auto known = by_word_.find(word); known != by_word_.end()) return known->second;
  if (!glyphs_) glyphs_ = std::make_unique<ClassicDrawerGlyphs>(ClassicDrawerGlyphs::load(data_dir_));
  const std::vector<TracePoint3> expert_points = writing_trace_points(expert);
  std::vector<ExecutionReference> out;
  if (expert_points.empty()) return by_word_[word] = out;
  for (int drawer : training_drawers()) {
    const std::vector<int> drawers(word.size(), drawer);
    const WrittenWord written = onto_expert_start(written_word(*glyphs_, word, drawers), expert_points.front());
    ExecutionReference r;
    r.name = "the letters of Omniglot drawer " + std::to_string(drawer);
    r.steps = writing_step_sequence(unsampled(written).trace, writing::AlphabetKind::Classic, word);
    r.from_expert = coarse_same_word(expert, r.steps);
    out.push_back(std::move(r));
  }
  return by_word_[word] = out;
}

}  // namespace sc
