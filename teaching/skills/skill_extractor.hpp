#pragma once
// The SkillExtractor interface: turns one trajectory into a sequence of skill segments.
// Task-agnostic: each task converts its trials into a StepSequence first (see the task's adapter).
// No torch types appear here; CompILE lives behind a pimpl in compile_extractor.hpp.
#include <memory>
#include <string>
#include <vector>

namespace sc {

// T steps of a trajectory: states[t] is the state *before* actions[t] (row-major, float).
struct StepSequence {
  int state_dim = 0;
  int action_dim = 0;
  std::vector<float> states;   // T x state_dim (may be empty when state_dim == 0)
  std::vector<float> actions;  // T x action_dim
  int length() const { return action_dim > 0 ? static_cast<int>(actions.size()) / action_dim : 0; }
};

// One segment: skill id and the half-open interval [begin, end) of action indices.
struct SkillSegment {
  int skill = 0;
  int begin = 0;
  int end = 0;
  int length() const { return end - begin; }
  bool operator==(const SkillSegment&) const = default;
};

// Segments in time order; empty segments are dropped, so the list covers [0, T) without gaps.
struct Segmentation {
  std::vector<SkillSegment> segments;
  std::vector<int> skills() const {
    std::vector<int> ids;
    ids.reserve(segments.size());
    for (const auto& s : segments) ids.push_back(s.skill);
    return ids;
  }
  bool operator==(const Segmentation&) const = default;
};

class SkillExtractor {
 public:
  virtual ~SkillExtractor() = default;
  // Deterministic: the same input always gives the same segmentation.
  virtual Segmentation extract(const StepSequence& trajectory) const = 0;
  // Batched form (implementations may run all trajectories at once).
  virtual std::vector<Segmentation> extract_all(const std::vector<StepSequence>& trajectories) const {
    std::vector<Segmentation> out;
    out.reserve(trajectories.size());
    for (const auto& t : trajectories) out.push_back(extract(t));
    return out;
  }
  virtual int num_skills() const = 0;    // skill ids are in [0, num_skills())
  virtual std::string name() const = 0;  // "compile" or "time-heuristic"
  // True when the extractor cuts whatever it is given into fixed slices of time (the paper's time heuristic):
  // it is given whole trajectories, since reading one in pieces would change what the baseline is.
  virtual bool slices_by_time() const { return false; }
};

}  // namespace sc
