#pragma once
// SkillExtractor backed by a trained CompILE model: argmax boundaries and skills, deterministic.
#include <filesystem>
#include <memory>
#include <string>

#include "teaching/skills/compile_model.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

class CompileExtractor final : public SkillExtractor {
 public:
  explicit CompileExtractor(std::shared_ptr<const CompileModel> model);
  // Loads a model file (see CompileModel::load for the checks and errors).
  static CompileExtractor load(const std::filesystem::path& file, const std::string& expected_task = "",
                               int expected_state_dim = -1, int expected_action_dim = -1);

  Segmentation extract(const StepSequence& trajectory) const override;
  std::vector<Segmentation> extract_all(const std::vector<StepSequence>& trajectories) const override;
  int num_skills() const override;
  std::string name() const override { return "compile"; }
  const CompileModel& model() const { return *model_; }

 private:
  std::shared_ptr<const CompileModel> model_;
};

}  // namespace sc
