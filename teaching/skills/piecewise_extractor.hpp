#pragma once
// A trajectory much longer than the model's training data is read in pieces about as long as them.
//
// Why: CompILE cuts a trajectory into at most K segments and puts each boundary at the most likely place anywhere
// after the previous one. A learner who does not park keeps driving until the time limit, three or four times as long
// as the expert; read in one piece, the expert's short last skill shares a long segment with whatever came after it,
// and Alg. 2 counts it as never done. More passes for a long drive did not help (the extra boundaries landed in its
// last steps); pieces as long as the expert's drives did, most for weak steering (docs/skills.md, *A learner who
// keeps driving until the time limit*).
//
// Spec:
//  * piece_count(T, L) = max(1, round(T / L)), halves rounded up: a trajectory shorter than 1.5 L is one piece, so
//    anything about as long as the model's data is read exactly as before;
//  * the n pieces are consecutive and cover [0, T): piece k is [floor(T k / n), floor(T (k + 1) / n)), so each is
//    between 0.75 L and 1.5 L long;
//  * each piece is segmented by the wrapped extractor (all pieces of all trajectories in one extract_all call) and
//    the segments are moved to the piece's place; a boundary therefore falls at every piece's start;
//  * name() and num_skills() are the wrapped extractor's. InputError for no extractor or a piece length < 1.
#include <memory>
#include <string>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

int piece_count(int length, int piece_length);
// The shortest trajectory read in more than one piece: ceil(1.5 L).
int shortest_split_length(int piece_length);

class PiecewiseExtractor final : public SkillExtractor {
 public:
  PiecewiseExtractor(std::shared_ptr<const SkillExtractor> inner, int piece_length);

  Segmentation extract(const StepSequence& trajectory) const override;
  std::vector<Segmentation> extract_all(const std::vector<StepSequence>& trajectories) const override;
  int num_skills() const override { return inner_->num_skills(); }
  std::string name() const override { return inner_->name(); }
  int piece_length() const { return piece_length_; }

 private:
  std::shared_ptr<const SkillExtractor> inner_;
  int piece_length_;
};

}  // namespace sc
