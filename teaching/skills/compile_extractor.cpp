#include "teaching/skills/compile_extractor.hpp"

namespace sc {

CompileExtractor::CompileExtractor(std::shared_ptr<const CompileModel> model) : model_(std::move(model)) {}

CompileExtractor CompileExtractor::load(const std::filesystem::path& file, const std::string& expected_task,
                                        int expected_state_dim, int expected_action_dim) {
  return CompileExtractor(std::make_shared<const CompileModel>(
      CompileModel::load(file, expected_task, expected_state_dim, expected_action_dim)));
}

Segmentation CompileExtractor::extract(const StepSequence& trajectory) const {
  return model_->segment({trajectory}).front();
}

std::vector<Segmentation> CompileExtractor::extract_all(const std::vector<StepSequence>& trajectories) const {
  return model_->segment(trajectories);
}

int CompileExtractor::num_skills() const { return model_->config().latent_size; }

}  // namespace sc
