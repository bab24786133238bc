#pragma once
// Boundary precision/recall/F1 of a segmentation against known boundaries (evaluate-skills, tests).
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

struct BoundaryScore {
  int true_positives = 0;
  int false_positives = 0;
  int false_negatives = 0;
  double precision() const;  // 1 when nothing was predicted
  double recall() const;     // 1 when there was nothing to find
  double f1() const;
  BoundaryScore& operator+=(const BoundaryScore& other);
};

// Interior boundaries of a segmentation: every segment end except the last (the trajectory's end).
std::vector<int> interior_boundaries(const Segmentation& segmentation);

// One-to-one matching (greedy by distance) of predicted to true interior boundaries; a prediction counts
// if it lies within `tolerance` steps of an unmatched true boundary.
BoundaryScore score_boundaries(const std::vector<int>& predicted, const std::vector<int>& truth, int tolerance);

}  // namespace sc
