#pragma once
// The paper's two synthetic parking students (appendix, "Hyperparameters"): 4-layer MLPs behaviour-cloned
// on goal-conditioned expert (state, action) pairs with Adam, lr 5e-4, batch 256 —
//   half-trained          50 epochs on all pairs (paper: eval MSE 0.049, "around 50 % more than a student
//                         trained for 400 epochs");
//   reversing difficulty  400 epochs on pairs where only 20 % of the reverse-acceleration pairs are kept
//                         (paper: eval MSE 0.021).
// and the yardstick both are measured against, the fully trained student (400 epochs on all pairs), which
// is not fine-tuned. The paper gives no hidden width; 256 is ours (recorded in the results).
#include <cstdint>
#include <string_view>
#include <vector>

#include "teaching/students/bc_policy.hpp"

namespace sc {

enum class SyntheticStudentKind { HalfTrained, ReversingDifficulty, FullyTrained };

inline constexpr SyntheticStudentKind kSyntheticStudentKinds[] = {SyntheticStudentKind::HalfTrained,
                                                                  SyntheticStudentKind::ReversingDifficulty};

// "half-trained", "reversing difficulty", "fully trained"
std::string_view student_name(SyntheticStudentKind kind);
// "half-trained", "reversing-difficulty", "fully-trained"
std::string_view student_key(SyntheticStudentKind kind);

struct SyntheticStudentRecipe {
  SyntheticStudentKind kind = SyntheticStudentKind::HalfTrained;
  int epochs = 50;
  double reverse_keep_fraction = 1.0;  // share of the u0 < 0 pairs kept in the training data
  int hidden = 256;

  static SyntheticStudentRecipe paper(SyntheticStudentKind kind);  // the values above
};

struct SyntheticStudent {
  SyntheticStudentRecipe recipe;
  BcPolicy policy;
  int training_pairs = 0;       // after the reverse filter
  int reverse_pairs_total = 0;  // u0 < 0 pairs in the expert data
  int reverse_pairs_kept = 0;
  double training_loss = 0.0;  // last epoch's mean MSE
  double expert_mse = 0.0;     // MSE on all expert pairs (incl. the dropped reverse ones)
  BcDataset training_data;     // the pairs it was cloned from (rehearsal material when fine-tuning)
};

// Deterministic in seed (network initialisation, reverse-pair sample, batch order).
SyntheticStudent train_synthetic_student(const SyntheticStudentRecipe& recipe, const BcDataset& expert_pairs,
                                         std::uint64_t seed);

}  // namespace sc
