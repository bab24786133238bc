#pragma once
// A trained CompILE model (reference-facts §3) behind a pimpl: no torch types here.
// Files: `<file>` is SkillCoach's binary model container (model_file.hpp: config + parameters + checksum,
// byte-identical for identical training runs) and `<file>.json` is a human-readable sidecar (format
// version, config, data description, seed, final metrics, git revision). Loading needs only `<file>`.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"
#include "teaching/skills/compile_config.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

// What the sidecar records besides the config (all optional).
struct ModelProvenance {
  std::string data_description;   // e.g. "1000 expert rollouts on random classic scenarios"
  std::string git_revision;       // empty when unknown
  Json metrics = Json::object();  // final metrics (e.g. from TrainingSummary)
  // Further sidecar entries written as given, e.g. a recorded noise floor kept when a model is re-saved
  // (set-readout); the fields above and the config take precedence over entries of the same name.
  Json extra = Json::object();
};

class CompileModel {
 public:
  struct Impl;
  explicit CompileModel(std::unique_ptr<Impl> impl);
  CompileModel(CompileModel&&) noexcept;
  CompileModel& operator=(CompileModel&&) noexcept;
  ~CompileModel();

  const CompileConfig& config() const;
  int parameter_count() const;

  // Segments in the trajectories' own action indices: eval mode, argmax boundaries and skills, no
  // gradients, all trajectories in one batch. Throws InputError if dimensions do not match the model.
  // A resampling model reads each trajectory at config().readout_phases phases and votes (phase_vote.hpp).
  std::vector<Segmentation> segment(const std::vector<StepSequence>& trajectories) const;
  // How many phases segment() reads; the weights are untouched. Throws InputError outside 1..16.
  void set_readout_phases(int phases);
  // Mean squared action reconstruction error per model step (eval mode, hard segments).
  double action_reconstruction_error(const std::vector<StepSequence>& trajectories) const;

  // Writes `file` and `file` + ".json". Throws InputError if they cannot be written.
  void save(const std::filesystem::path& file, const ModelProvenance& provenance = {}) const;
  // Throws InputError("<file>: <problem>") for a missing, truncated, corrupt or too-new file, for a model
  // of another task (expected_task non-empty) or with other dimensions (expected dims >= 0).
  static CompileModel load(const std::filesystem::path& file, const std::string& expected_task = "",
                           int expected_state_dim = -1, int expected_action_dim = -1);

  Impl& impl() { return *impl_; }
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

// Sidecar path for a model file: "<file>.json".
std::filesystem::path model_sidecar_path(const std::filesystem::path& file);

// Torch runs on one intra-op thread and OpenBLAS on one thread: on 2 cores, torch's 2 threads plus
// OpenBLAS's own threads were 3.8x slower (reference-baseline.md). Called by the trainer and the loader.
void configure_torch_threads();

}  // namespace sc
