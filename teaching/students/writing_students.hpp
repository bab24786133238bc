#pragma once
// Synthetic writing students (ours: the paper has synthetic students for parking only): pens behaviour-cloned
// (writing_pen_policy.hpp) on the expert words' (13-float state, pen step) pairs, each with one planted
// deficit, cut along the words' TRUE character boundaries (WordTrajectory::character_starts), not along
// the skills the diagnosis will look for:
//   missing letter X    every pair of every X in the words is left out: the pen never saw X written;
//   distorted letter X  X's pairs are kept with their steps mirrored vertically (dy -> -dy): the pen saw X
//                       only upside down (its end lands within 2 px of the true end: letters drift < 1 px);
//   half-trained        all pairs, a tenth of the epochs.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/writing/word_trajectory.hpp"
#include "teaching/students/bc_policy.hpp"

namespace sc {

enum class PenDeficit { MissingLetter, DistortedLetter, HalfTrained };

struct WritingStudentRecipe {
  PenDeficit deficit = PenDeficit::MissingLetter;
  char letter = 'a';  // the letter of MissingLetter / DistortedLetter
  int epochs = 30;
  int hidden = 128;
  double learning_rate = 1e-3;
  int batch_size = 256;

  std::string name() const;  // "missing 'a'", "distorted 'a'", "half-trained"
  std::string key() const;   // "missing-a", "distorted-a", "half-trained"
  // The default students: missing a, b, c, t, e; distorted a; half-trained (epochs / 10).
  static std::vector<WritingStudentRecipe> defaults(int epochs);
};

// The expert words' raw pairs in order, each labelled with the symbol it belongs to.
struct LabelledPenPairs {
  BcDataset pairs;           // raw 13-D states, 2-D steps
  std::vector<char> symbol;  // one per pair
};
LabelledPenPairs labelled_pen_pairs(const std::vector<writing::WordTrajectory>& words);

// The raw pairs the recipe's student is cloned from. InputError for a letter that is not a classic letter.
BcDataset deficit_pairs(const LabelledPenPairs& expert, const WritingStudentRecipe& recipe);

struct WritingStudent {
  WritingStudentRecipe recipe;
  BcPolicy policy;
  BcDataset training_data;     // network units (rehearsal material when fine-tuning)
  int letter_pairs = 0;        // expert pairs of the recipe's letter (left out or mirrored)
  double training_loss = 0.0;  // last epoch's mean MSE (network units)
  double expert_mse = 0.0;     // MSE on all expert pairs, undistorted (network units)
};

// Deterministic in seed (initialisation and batch order).
WritingStudent train_writing_student(const WritingStudentRecipe& recipe, const LabelledPenPairs& expert,
                                     std::uint64_t seed);

}  // namespace sc
