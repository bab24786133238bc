#include "teaching/students/writing_students.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/writing/step_data.hpp"
#include "teaching/students/writing_pen_policy.hpp"

namespace sc {
namespace {

constexpr std::string_view kClassicLetters = "abcte";

void check_letter(char letter) {
  if (kClassicLetters.find(letter) == std::string_view::npos)
    throw InputError("writing student", std::string("'") + letter + "' is not a classic letter (a b c t e)");
}

}  // namespace

std::string WritingStudentRecipe::name() const {
  switch (deficit) {
    case PenDeficit::MissingLetter:
      return std::string("missing '") + letter + "'";
    case PenDeficit::DistortedLetter:
      return std::string("distorted '") + letter + "'";
    case PenDeficit::HalfTrained:
      break;
  }
  return "half-trained";
}

std::string WritingStudentRecipe::key() const {
  switch (deficit) {
    case PenDeficit::MissingLetter:
      return std::string("missing-") + letter;
    case PenDeficit::DistortedLetter:
      return std::string("distorted-") + letter;
    case PenDeficit::HalfTrained:
      break;
  }
  return "half-trained";
}

std::vector<WritingStudentRecipe> WritingStudentRecipe::defaults(int epochs) {
  std::vector<WritingStudentRecipe> out;
  for (char letter : kClassicLetters) {
    WritingStudentRecipe r;
    r.letter = letter;
    r.epochs = epochs;
    out.push_back(r);
  }
  WritingStudentRecipe distorted;
  distorted.deficit = PenDeficit::DistortedLetter;
  distorted.epochs = epochs;
  out.push_back(distorted);
  WritingStudentRecipe half;
  half.deficit = PenDeficit::HalfTrained;
  half.epochs = std::max(1, epochs / 10);
  out.push_back(half);
  return out;
}

LabelledPenPairs labelled_pen_pairs(const std::vector<writing::WordTrajectory>& words) {
  LabelledPenPairs out;
  for (const writing::WordTrajectory& w : words) {
    const writing::WritingStepData data = writing::expert_step_data(w);
    BcDataset one;
    one.state_dim = data.state_dim;
    one.action_dim = data.action_dim;
    one.states = data.states;
    one.actions = data.actions;
    out.pairs.append(one);
    for (int t = 0, k = 0; t < data.length(); ++t) {
      while (k + 1 < static_cast<int>(w.character_starts.size()) &&
             w.character_starts[static_cast<std::size_t>(k + 1)] <= t)
        ++k;
      out.symbol.push_back(w.word[static_cast<std::size_t>(k)]);
    }
  }
  return out;
}

BcDataset deficit_pairs(const LabelledPenPairs& expert, const WritingStudentRecipe& recipe) {
  if (recipe.deficit == PenDeficit::HalfTrained) return expert.pairs;
  check_letter(recipe.letter);
  BcDataset out;
  out.state_dim = expert.pairs.state_dim;
  out.action_dim = expert.pairs.action_dim;
  const auto sd = static_cast<std::size_t>(out.state_dim), ad = static_cast<std::size_t>(out.action_dim);
  for (std::size_t i = 0; i < expert.symbol.size(); ++i) {
    const bool letter = expert.symbol[i] == recipe.letter;
    if (letter && recipe.deficit == PenDeficit::MissingLetter) continue;
    out.states.insert(out.states.end(), expert.pairs.states.begin() + static_cast<long>(i * sd),
                      expert.pairs.states.begin() + static_cast<long>((i + 1) * sd));
    out.actions.push_back(expert.pairs.actions[i * ad]);
    out.actions.push_back(letter ? -expert.pairs.actions[i * ad + 1] : expert.pairs.actions[i * ad + 1]);
  }
  return out;
}

WritingStudent train_writing_student(const WritingStudentRecipe& recipe, const LabelledPenPairs& expert,
                                     std::uint64_t seed) {
  const BcDataset expert_units = pen_dataset(expert.pairs);
  WritingStudent s{recipe,
                   BcPolicy(expert_units.state_dim, expert_units.action_dim, recipe.hidden, seed),
                   pen_dataset(deficit_pairs(expert, recipe)),
                   0,
                   0.0,
                   0.0};
  if (recipe.deficit != PenDeficit::HalfTrained)
    s.letter_pairs = static_cast<int>(std::count(expert.symbol.begin(), expert.symbol.end(), recipe.letter));
  BcTrainingConfig config;
  config.epochs = recipe.epochs;
  config.learning_rate = recipe.learning_rate;
  config.batch_size = recipe.batch_size;
  config.seed = seed;
  s.training_loss = s.policy.train(s.training_data, config);
  s.expert_mse = s.policy.evaluate(expert_units);
  return s;
}

}  // namespace sc
