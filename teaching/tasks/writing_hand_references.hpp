#pragma once
// The expert's classic word written in other drawers' hands: the references quality-aware expertise may
// take as a learner's own hand (teaching/expertise/execution_reference.hpp).
//
// Why drawers 1-10 only: those are the hands the skill model's training copies are written by; drawers
// 11-15 stay unseen, so that learners writing in those hands (evaluate-skills --planted-weaknesses
// --own-hands) measure a hand the references do not contain - as every real learner's is.
//
// Spec: reference d writes every letter of the word after drawer d (written_word, no noise, the drawer's own
// size, as a learner writing in that hand), moved onto the expert's first point; its steps are
// writing_step_sequence's; from_expert is align_same_word on every 8th step of both, spread back over the
// steps between.
// Computed once per word and kept (the pre-test asks for the same words for every learner); safe to call
// from several threads.
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "teaching/expertise/execution_reference.hpp"
#include "teaching/tasks/writing_realistic_learner.hpp"

namespace sc {

class WritingHandReferences {
 public:
  explicit WritingHandReferences(std::filesystem::path data_dir);
  // One reference per drawer of training_drawers(), in that order. Throws InputError for a word that is not
  // classic or unreadable stroke files.
  std::vector<ExecutionReference> references(const std::string& word, const StepSequence& expert) const;

 private:
  std::filesystem::path data_dir_;
  mutable std::mutex mutex_;
  mutable std::unique_ptr<ClassicDrawerGlyphs> glyphs_;  // loaded at the first call
  mutable std::map<std::string, std::vector<ExecutionReference>> by_word_;
};

}  // namespace sc
