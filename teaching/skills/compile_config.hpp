#pragma once
// Hyperparameters of a CompILE model and of its training run (no torch here).
// Defaults follow the paper's configs (reference-facts §3.1); see parking_defaults()/writing_defaults().
#include <cstdint>
#include <string>

#include "engine/core/json_file.hpp"
#include "engine/core/task_kind.hpp"

namespace sc {

// What the decoder reconstructs (reference `--mode`):
//   action            actions only;
//   state+action      actions and states (weighted by beta_s);
//   statediff+action  actions and state differences s_{t+1}-s_t (weighted by beta_s); the encoder still
//                     sees raw states, as in the reference.
enum class CompileMode { Action, StateAction, StateDiffAction };

std::string to_string(CompileMode mode);
// Throws InputError("<where>", "unknown CompILE mode ...") for anything else.
CompileMode parse_compile_mode(const std::string& text, const std::string& where);

struct CompileConfig {
  std::string task = "synthetic";  // "parking", "writing", ...: checked when a model is loaded
  CompileMode mode = CompileMode::Action;
  int state_dim = 0;  // taken from the data when training
  int action_dim = 2;
  int latent_size = 16;      // M: number of discrete skills (concrete latent)
  int num_segments = 4;      // K
  int hidden = 64;           // H
  double prior_rate = 10.0;  // Poisson rate (segment length in model steps)
  double beta_b = 0.1;
  double beta_z = 0.1;
  double beta_s = 0.0;
  double learning_rate = 1e-3;  // Adam
  int batch_size = 100;
  int iterations = 2000;  // passes over the training split (the reference's "iterations")
  int eval_interval = 5;  // iterations between validation checks
  int patience = 50;      // stop after this many validation checks without improvement
  std::uint64_t seed = 0;
  // Independent trainings from seeds seed, seed + 1, ...; the one with the lowest validation NLL is kept.
  // CompILE's relaxed objective has poor local minima (measured on planted data: the same config reached
  // boundary F1 0.59..1.00 depending on the seed, and the validation NLL ranks the runs correctly), so
  // picking the best of a few runs is the cheapest reliable fix. Runs go in parallel, one per core.
  int restarts = 1;
  // Arc-length resampling before the model (0 = off). Actions are read as displacements; each model step
  // covers `resample_step` units of path length and its action is the mean unit direction over it.
  double resample_step = 0.0;
  // Segmenting (not training) reads a resampled trajectory at this many phases of the resampling and keeps
  // what most of them agree on (phase_vote.hpp: why, and the vote). 1 = one reading, from the first point.
  int readout_phases = 1;
  // Iterations of warm start before ordinary training (0 = off): every boundary is fixed at the places
  // where the training data stop repeating (find_repeat_boundaries, no true boundaries involved) while the
  // decoder and latent heads learn to reconstruct those segments and the boundary head learns to predict
  // them (a cross-entropy term); then CompILE trains as usual from there. Why: from random weights the
  // writing model settles on stroke pieces although letters score better on its own objective
  // (docs/skills.md). Data that do not repeat exactly (parking) yield no boundaries: keep it 0 there.
  int warm_start_iterations = 0;
  double warm_start_learning_rate = 0.0;  // Adam's rate during the warm start (0 = learning_rate)
  // Training feeds the decoder the one-hot skill of each relaxed latent sample (straight-through Gumbel:
  // the gradient is the relaxed sample's). Why: segmenting reads the argmax skill, but a decoder trained on
  // soft mixtures can tell two letters apart by mixtures that share their largest weight, so two letters
  // end up one skill at read-out. With hard codes in training, merging two letters costs reconstruction.
  bool straight_through_latents = false;
  // The warm start also trains the latent head to give each repeated unit (repeat_units: segments equal
  // step for step, as the warm start's boundaries cut them) a skill of its own, unit u -> skill u, by a
  // cross-entropy term. Why: from reconstruction alone the warm start lets two letters share one skill, and
  // which ones depends on the seed (docs/skills.md); the units are found the way the boundaries are, from
  // what repeats, never from the true symbols. Needs warm_start_iterations > 0.
  bool warm_start_units = false;
  // Weight of that unit term against the reconstruction NLL (the boundary term has weight 1). Measured: at
  // weight 1 one restart in three ended the warm start with two letters still on one skill (docs/skills.md);
  // choose_restart (restart_choice.hpp) does not keep such a restart while another separated its units.
  double warm_start_unit_weight = 1.0;
  // Weight of a bonus for using many skills: the loss subtracts beta_usage times the entropy of the batch's
  // mean latent posterior (over every segment of every trajectory). Why: a skill that starts out covering
  // two letters keeps both, because an unused skill's decoder is untrained and moving one letter there first
  // costs reconstruction; the bonus pays for that move. 0 = off (the paper's objective).
  double beta_usage = 0.0;
  // The encoder reads the actions beside the states (the paper's configuration). false: it reads the
  // states only (its action embedding gets zeros), so where the model cuts and which skill it names depend on
  // the motion alone; the decoder still reconstructs the actions. Why: a keyboard gives other action values
  // for the same motion, and an encoder reading them names other skills (docs/skills.md, parking). Needs a
  // mode with states.
  bool encoder_reads_actions = true;

  // Paper: latent 16, K 4, Poisson 10, beta_s 1, statediff+action, lr 1e-3, batch 100 (12-D states).
  static CompileConfig parking_defaults();
  // Paper: latent 24, K 8, action, lr 5e-3, batch 50; we resample, warm-start and use lr 1e-3 without the
  // latent KL (see compile_config.cpp).
  static CompileConfig writing_defaults();
  // Task defaults by name ("parking" or "writing"); throws InputError otherwise.
  static CompileConfig defaults_for(TaskKind task);
  static CompileConfig defaults_for(const std::string& task);  // InputError for a name that is not a task

  bool uses_states() const { return mode != CompileMode::Action; }
  // Throws InputError naming `where` when a value is out of range.
  void validate(const std::string& where) const;
};

// Fields that are off by default and newer than the shipped models are written only when on (so those models
// save byte for byte as before); `every_field` writes them all (train-skills' --set keys).
Json to_json(const CompileConfig& config, bool every_field = false);
// Reads the fields written by to_json; errors name `view`'s file and JSON path.
CompileConfig compile_config_from_json(const JsonView& view);

}  // namespace sc
