#include "teaching/students/synthetic_students.hpp"

#include "teaching/students/bc_datasets.hpp"

namespace sc {

std::string_view student_name(SyntheticStudentKind kind) {
  switch (kind) {
    case SyntheticStudentKind::HalfTrained:
      return "half-trained";
    case SyntheticStudentKind::ReversingDifficulty:
      return "reversing difficulty";
    case SyntheticStudentKind::FullyTrained:
      break;
  }
  return "fully trained";
}

std::string_view student_key(SyntheticStudentKind kind) {
  switch (kind) {
    case SyntheticStudentKind::HalfTrained:
      return "half-trained";
    case SyntheticStudentKind::ReversingDifficulty:
      return "reversing-difficulty";
    case SyntheticStudentKind::FullyTrained:
      break;
  }
  return "fully-trained";
}

SyntheticStudentRecipe SyntheticStudentRecipe::paper(SyntheticStudentKind kind) {
  SyntheticStudentRecipe r;
  r.kind = kind;
  if (kind != SyntheticStudentKind::HalfTrained) r.epochs = 400;
  if (kind == SyntheticStudentKind::ReversingDifficulty) r.reverse_keep_fraction = 0.2;
  return r;
}

SyntheticStudent train_synthetic_student(const SyntheticStudentRecipe& recipe, const BcDataset& expert_pairs,
                                         std::uint64_t seed) {
  const BcDataset data = keep_reverse_fraction(expert_pairs, recipe.reverse_keep_fraction, seed ^ 0x5eedULL);
  SyntheticStudent s{
      recipe, BcPolicy(expert_pairs.state_dim, expert_pairs.action_dim, recipe.hidden, seed), 0, 0, 0, 0.0, 0.0, data};
  s.training_pairs = data.size();
  s.reverse_pairs_total = count_reverse_pairs(expert_pairs);
  s.reverse_pairs_kept = count_reverse_pairs(data);
  BcTrainingConfig config;
  config.epochs = recipe.epochs;
  config.seed = seed;
  s.training_loss = s.policy.train(data, config);
  s.expert_mse = s.policy.evaluate(expert_pairs);
  return s;
}

}  // namespace sc
