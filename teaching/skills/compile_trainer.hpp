#pragma once
// Trains a CompILE model on task-agnostic StepSequences (no torch types here).
//
// One iteration is one pass over the training split in batches of config.batch_size (shuffled with the
// seed). Every config.eval_interval iterations the eval-mode reconstruction NLL on the VALID split is
// measured; training stops after config.patience checks without improvement and the BEST weights are
// kept. (The reference measured on its eval split and saved every 5 epochs rather than the best, so its
// shipped models were arbitrary snapshots: reference-facts §3.6, §6.5, §6.10.)
// With config.restarts > 1, that many runs (seeds seed, seed + 1, ...) train in parallel (one thread per
// core, each run single-threaded) and one is kept by choose_restart (restart_choice.hpp): the lowest
// validation NLL (or the highest review score, review_restarts_with) among the runs whose warm start separated
// its units; ties go to the lower seed. Without a validation split or score the first such run is kept.
// With config.warm_start_iterations > 0 (and boundaries not fixed), each run first trains with the boundaries
// fixed where the training data stop repeating (find_repeat_boundaries) and the boundary head supervised
// towards them; the weights it leaves are the first candidate for "best" (best_iteration 0).
// Deterministic: the same config (seed) and data on the same machine give byte-identical model files,
// whatever the thread scheduling (runs share nothing).
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "teaching/skills/compile_model.hpp"

namespace sc {

struct TrainingProgress {
  int restart = 0;  // 0-based run of config.restarts (runs may report interleaved)
  int restarts = 1;
  int iteration = 0;   // 1-based
  int iterations = 0;  // configured maximum
  double loss = 0.0;   // training loss terms, mean over the iteration's trajectories
  double nll_action = 0.0;
  double nll_state = 0.0;
  double kl_z = 0.0;
  double kl_b = 0.0;
  double boundary_ce = 0.0;  // warm start only: cross-entropy of the boundary head against the fixed boundaries
  double unit_ce = 0.0;      // warm start with warm_start_units: cross-entropy of the latent head against the units
  bool warm_start = false;   // a warm-start iteration (config.warm_start_iterations); then iteration counts those
  double valid_nll = std::numeric_limits<double>::quiet_NaN();  // NaN when not evaluated this iteration
  double best_valid_nll = std::numeric_limits<double>::quiet_NaN();
  double elapsed_seconds = 0.0;
  double phase_start_seconds = 0.0;  // elapsed_seconds when this phase (warm start or training) began: for the ETA
  bool improved = false;
};

struct TrainingSummary {
  int restart = 0;                        // the run whose weights were kept (choose_restart)
  std::vector<double> restart_valid_nll;  // best validation NLL of every run (NaN without a valid split)
  std::vector<double> restart_unit_term;  // every run's warm_start_unit_term
  std::vector<double> restart_score;      // every run's review score (review_restarts_with; empty without one)
  int iterations_run = 0;
  int best_iteration = 0;  // iteration whose weights were kept (0 = before the first: untrained, or as warm-started)
  double best_valid_nll = std::numeric_limits<double>::quiet_NaN();
  double final_loss = std::numeric_limits<double>::quiet_NaN();
  double seconds = 0.0;
  bool stopped_early = false;
  // Warm start (config.warm_start_iterations > 0): mean number of repetition boundaries per training trajectory.
  double warm_start_boundaries = std::numeric_limits<double>::quiet_NaN();
  double warm_start_valid_nll = std::numeric_limits<double>::quiet_NaN();  // of the weights the warm start left
  // With warm_start_units: the unit cross-entropy of the warm start's last pass, per trajectory (else NaN).
  double warm_start_unit_term = std::numeric_limits<double>::quiet_NaN();
  Json to_json() const;
};

class CompileTrainer {
 public:
  using ProgressCallback = std::function<void(const TrainingProgress&)>;
  explicit CompileTrainer(CompileConfig config);

  // `train` must not be empty; `valid` may be (then the last weights are kept). Dimensions must match the
  // config (state_dim is only checked in state modes). Throws InputError for bad data or config.
  // `progress` is called from the training threads, one call at a time.
  CompileModel train(const std::vector<StepSequence>& train, const std::vector<StepSequence>& valid,
                     const ProgressCallback& progress = {});
  const TrainingSummary& summary() const { return summary_; }

  // Diagnostic: from now on train() fixes every boundary instead of sampling it. Entry i lists trajectory i's
  // interior boundaries (action indices, strictly ascending, inside 1..T-1, at most K-1 of them; missing
  // ones fall at the end, i.e. empty last segments). Only the latent heads and the decoder then learn from
  // reconstruction (the boundary head sees only the prior), so such a model measures what CompILE's
  // objective gives a chosen segmentation (its validation NLL); it is not meant for segmenting.
  // train() throws InputError when the lists do not match the data.
  void fix_boundaries(std::vector<std::vector<int>> train_boundaries, std::vector<std::vector<int>> valid_boundaries);
  // The warm start (config.warm_start_iterations > 0) fixes the boundaries here instead of where the training
  // data stop repeating: for augmented copies of repeating data, which inherit their clean word's repetition
  // boundaries (the perturbation keeps step indices). Entry i belongs to training trajectory i; same rules
  // as fix_boundaries (train() throws InputError when they do not match the data).
  // `units` (config.warm_start_units): per trajectory the repeated unit of each of its segments (one more
  // entry than boundaries; -1 = none, else < latent_size), e.g. the clean word's repeat_units inherited by
  // its copies. Without them, train() finds the units itself by exact repetition in the training data.
  void warm_start_at(std::vector<std::vector<int>> train_boundaries, std::vector<std::vector<int>> units = {});

  // After every restart has trained, `review` is called once per restart (in order, on train()'s thread) with
  // its model and returns its score for choose_restart (higher is better; NaN: none): a measure the trainer
  // cannot take itself, e.g. writing's cross-hand consistency (train-skills). It may also keep the model.
  using RestartReview = std::function<double(const CompileModel& model, int restart)>;
  void review_restarts_with(RestartReview review);

 private:
  CompileConfig config_;
  TrainingSummary summary_;
  std::vector<std::vector<int>> fixed_train_, fixed_valid_;
  bool fixed_ = false;
  std::vector<std::vector<int>> warm_given_, warm_units_given_;
  bool warm_given_set_ = false;
  RestartReview review_;
};

}  // namespace sc
