// CompileTrainer: Adam on the relaxed CompILE loss, early stopping on the valid split, best weights kept;
// several runs (restarts) in parallel, one kept (choose_restart: validation NLL or the caller's score, and the
// warm start's unit term).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <numeric>
#include <thread>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "teaching/skills/compile_torch.hpp"
#include "teaching/skills/compile_trainer.hpp"
#include "teaching/skills/repeat_boundaries.hpp"
#include "teaching/skills/restart_choice.hpp"

namespace sc {

using compile_detail::Batch;
using compile_detail::CompileNetwork;

CompileTrainer::CompileTrainer(CompileConfig config) : config_(std::move(config)) {}

void CompileTrainer::fix_boundaries(std::vector<std::vector<int>> train_boundaries,
                                    std::vector<std::vector<int>> valid_boundaries) {
  fixed_train_ = std::move(train_boundaries);
  fixed_valid_ = std::move(valid_boundaries);
  fixed_ = true;
}

void CompileTrainer::review_restarts_with(RestartReview review) { review_ = std::move(review); }

void CompileTrainer::warm_start_at(std::vector<std::vector<int>> train_boundaries,
                                   std::vector<std::vector<int>> units) {
  warm_given_ = std::move(train_boundaries);
  warm_units_given_ = std::move(units);
  warm_given_set_ = true;
}

namespace {

// Boundary positions in model steps (empty when boundaries are not fixed), one list per trajectory.
using FixedPositions = std::vector<std::vector<int>>;

// Per trajectory the unit of each of the model's K segments (-1 = none): the warm start's unit targets.
using SegmentUnits = std::vector<std::vector<int>>;

// The batch of data[indices[i]] (with their fixed boundaries and segment units, if any), in that order.
Batch batch_of(const std::vector<ModelSteps>& data, const FixedPositions& fixed,
               const std::vector<std::size_t>& indices, const CompileConfig& config, bool supervise = false,
               const SegmentUnits& units = {}) {
  std::vector<const StepSequence*> steps;
  std::vector<const std::vector<int>*> boundaries;
  for (std::size_t i : indices) {
    steps.push_back(&data[i].steps);
    if (!fixed.empty()) boundaries.push_back(&fixed[i]);
  }
  Batch batch = compile_detail::make_batch(steps, config, boundaries);
  batch.supervise_boundaries = supervise && !fixed.empty();
  if (supervise && !units.empty())
    for (std::size_t row : batch.source) batch.segment_units.push_back(units[indices[row]]);
  return batch;
}

std::vector<Batch> fixed_batches(const std::vector<ModelSteps>& data, const FixedPositions& fixed,
                                 const CompileConfig& config) {
  std::vector<Batch> out;
  const auto bs = static_cast<std::size_t>(config.batch_size);
  for (std::size_t first = 0; first < data.size(); first += bs) {
    std::vector<std::size_t> chunk;
    for (std::size_t i = first; i < std::min(data.size(), first + bs); ++i)
      if (data[i].steps.length() > 0) chunk.push_back(i);
    if (!chunk.empty()) out.push_back(batch_of(data, fixed, chunk, config));
  }
  return out;
}

// Maps each trajectory's interior boundaries (action indices) to the K-1 boundary positions of the model:
// a boundary at action b becomes the first model step that starts at or after b; missing ones go to the
// end. Throws InputError naming `what` when a list does not fit its trajectory.
FixedPositions to_fixed_positions(const std::vector<std::vector<int>>& boundaries, const std::vector<ModelSteps>& steps,
                                  int num_segments, const std::string& what) {
  if (boundaries.size() != steps.size())
    throw InputError(what, std::to_string(boundaries.size()) + " boundary lists for " + std::to_string(steps.size()) +
                               " trajectories");
  FixedPositions out;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const std::string where = what + " " + std::to_string(i);
    const auto& begin = steps[i].original_begin;
    const int length = begin.back(), model_length = steps[i].steps.length();
    if (boundaries[i].size() > static_cast<std::size_t>(num_segments - 1))
      throw InputError(where, std::to_string(boundaries[i].size()) + " boundaries, the model has only " +
                                  std::to_string(num_segments - 1));
    std::vector<int> positions;
    int previous = 0;
    for (int b : boundaries[i]) {
      if (b <= previous || b >= length)
        throw InputError(where,
                         "boundary " + std::to_string(b) + " is not ascending inside 1.." + std::to_string(length - 1));
      previous = b;
      const auto at = std::lower_bound(begin.begin(), begin.end(), b) - begin.begin();
      positions.push_back(std::clamp(static_cast<int>(at), 1, std::max(1, model_length)));
    }
    positions.resize(static_cast<std::size_t>(num_segments - 1), std::max(1, model_length));
    out.push_back(std::move(positions));
  }
  return out;
}

// The units of each trajectory's segments (one more than its boundaries) spread over the model's K
// segments at `positions` (to_fixed_positions of those boundaries): segments past the last boundary, and
// segments that resampling left without a model step, get none (-1). Throws InputError naming `what` for
// a list of the wrong length or a unit outside 0..latent_size-1.
SegmentUnits to_segment_units(const std::vector<std::vector<int>>& units,
                              const std::vector<std::vector<int>>& boundaries, const FixedPositions& positions,
                              int latent_size, const std::string& what) {
  if (units.size() != boundaries.size())
    throw InputError(
        what, std::to_string(units.size()) + " unit lists for " + std::to_string(boundaries.size()) + " trajectories");
  SegmentUnits out;
  for (std::size_t i = 0; i < units.size(); ++i) {
    const std::string where = what + " " + std::to_string(i);
    if (units[i].size() != boundaries[i].size() + 1)
      throw InputError(where, std::to_string(units[i].size()) + " units for " +
                                  std::to_string(boundaries[i].size() + 1) + " segments");
    std::vector<int> row(positions[i].size() + 1, -1);
    for (std::size_t j = 0; j < units[i].size(); ++j) {
      const int u = units[i][j];
      if (u < -1 || u >= latent_size)
        throw InputError(where, "unit " + std::to_string(u) + " is not a skill of the model (0.." +
                                    std::to_string(latent_size - 1) + ")");
      const int begin = j == 0 ? 0 : positions[i][j - 1];
      const bool has_steps = j >= positions[i].size() || positions[i][j] > begin;
      if (has_steps) row[j] = u;
    }
    out.push_back(std::move(row));
  }
  return out;
}

// Eval-mode (hard) reconstruction NLL per trajectory: the early-stopping criterion.
double validation_nll(const CompileNetwork& net, const std::vector<Batch>& batches) {
  torch::NoGradGuard no_grad;
  double sum = 0.0;
  std::int64_t count = 0;
  for (const auto& batch : batches) {
    const auto l = compile_detail::compute_losses(net, batch, false, nullptr);
    sum += (l.nll_action + net.config.beta_s * l.nll_state).item<double>() * static_cast<double>(batch.size);
    count += batch.size;
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace

namespace {

// One training run (see CompileTrainer): its weights and summary.
struct RunResult {
  std::unique_ptr<CompileModel::Impl> impl;
  TrainingSummary summary;
};

// A fresh Fisher-Yates order of `order` (one call per pass, warm start and training alike).
void shuffle(std::vector<std::size_t>& order, Rng& rng) {
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
}

// One pass over the training split in its current order: an Adam step per batch; the loss terms are added
// to `p` as means over the pass's trajectories.
// With `supervise` (warm start) the boundary head is also trained towards the fixed boundaries.
void train_one_pass(const CompileNetwork& net, torch::optim::Adam& optimizer, at::Generator& generator,
                    const std::vector<ModelSteps>& train_steps, const FixedPositions& fixed,
                    const std::vector<std::size_t>& order, TrainingProgress& p, bool supervise = false,
                    const SegmentUnits& units = {}) {
  const auto batch_size = static_cast<std::size_t>(net.config.batch_size);
  for (std::size_t first = 0; first < order.size(); first += batch_size) {
    const std::vector<std::size_t> chunk(
        order.begin() + static_cast<std::ptrdiff_t>(first),
        order.begin() + static_cast<std::ptrdiff_t>(std::min(order.size(), first + batch_size)));
    const Batch batch = batch_of(train_steps, fixed, chunk, net.config, supervise, units);
    const auto losses = compile_detail::compute_losses(net, batch, true, &generator);
    optimizer.zero_grad();
    losses.total.backward();
    optimizer.step();
    const double w = static_cast<double>(batch.size) / static_cast<double>(order.size());
    p.loss += losses.total.item<double>() * w;
    p.nll_action += losses.nll_action.item<double>() * w;
    p.nll_state += losses.nll_state.item<double>() * w;
    p.kl_z += losses.kl_z.item<double>() * w;
    p.kl_b += losses.kl_b.item<double>() * w;
    p.boundary_ce += losses.boundary_ce.item<double>() * w;
    p.unit_ce += losses.unit_ce.item<double>() * w;
  }
}

// The data a run trains on: fixed boundaries (diagnostic) and the warm start's boundaries, both optional.
struct RunData {
  const std::vector<ModelSteps>& train_steps;
  const FixedPositions& fixed;
  const FixedPositions& warm;
  const SegmentUnits& warm_units;  // empty unless config.warm_start_units
  const std::vector<Batch>& valid_batches;
};

// Warm start (CompileConfig::warm_start_iterations): passes with the boundaries fixed at `warm` and the
// boundary head supervised towards them. No validation here: the best weights are chosen afterwards, by
// the model's own boundaries. Returns the unit term of the last pass (NaN without units).
double warm_start(const CompileNetwork& net, torch::optim::Adam& optimizer, at::Generator& generator,
                  const RunData& data, std::vector<std::size_t>& usable, Rng& shuffle_rng, int restart,
                  const std::function<double()>& elapsed, const std::function<void(TrainingProgress&)>& report) {
  const int count = net.config.warm_start_iterations;
  auto set_rate = [&](double rate) {
    for (auto& group : optimizer.param_groups()) static_cast<torch::optim::AdamOptions&>(group.options()).lr(rate);
  };
  if (net.config.warm_start_learning_rate > 0.0) set_rate(net.config.warm_start_learning_rate);
  double unit_term = std::numeric_limits<double>::quiet_NaN();
  for (int it = 1; it <= count; ++it) {
    shuffle(usable, shuffle_rng);
    TrainingProgress p;
    p.restart = restart;
    p.iteration = it;
    p.iterations = count;
    p.warm_start = true;
    train_one_pass(net, optimizer, generator, data.train_steps, data.warm, usable, p, true, data.warm_units);
    if (!std::isfinite(p.loss))
      throw InputError("compile training", "loss became non-finite in warm-start iteration " + std::to_string(it));
    p.elapsed_seconds = elapsed();
    report(p);
    if (!data.warm_units.empty()) unit_term = p.unit_ce;
  }
  set_rate(net.config.learning_rate);
  return unit_term;
}

// `seed` (config.seed + restart) draws the run's initial weights, Gumbel noise and batch order; the network
// keeps `config` as it is, so the model records the configured seed (that of the data and the split, which
// evaluate-skills must avoid) whichever run is kept.
RunResult train_run(const CompileConfig& config, std::uint64_t seed, int restart, const RunData& data,
                    std::vector<std::size_t> usable, const std::function<void(TrainingProgress&)>& report) {
  const auto& train_steps = data.train_steps;
  const auto& fixed = data.fixed;
  const auto& valid_batches = data.valid_batches;
  const auto start_time = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count(); };
  auto generator = at::detail::createCPUGenerator(seed);
  RunResult out{std::make_unique<CompileModel::Impl>(CompileModel::Impl{CompileNetwork(config, generator)}), {}};
  CompileNetwork& net = out.impl->net;
  TrainingSummary& summary = out.summary;
  std::vector<torch::Tensor> params = net.parameters();
  torch::optim::Adam optimizer(params, torch::optim::AdamOptions(config.learning_rate));
  Rng shuffle_rng = Rng(seed).fork(0x5eed5u);

  std::vector<torch::Tensor> best;
  double warm_valid_nll = std::numeric_limits<double>::quiet_NaN();
  if (!data.warm.empty()) {
    summary.warm_start_unit_term =
        warm_start(net, optimizer, generator, data, usable, shuffle_rng, restart, elapsed, report);
    // The warm-started weights are a candidate like any checkpoint (best_iteration 0): measured on the
    // writing words, the first free iterations at the usual learning rate undo the warm start (the
    // relaxed boundaries' Gumbel noise moves them off the letters), and early stopping must be able to
    // say so.
    if (!valid_batches.empty()) {
      summary.best_valid_nll = warm_valid_nll = validation_nll(net, valid_batches);
      for (const auto& t : params) best.push_back(t.detach().clone());
    }
  }
  const double phase_start = elapsed();
  int checks_without_improvement = 0;
  for (int it = 1; it <= config.iterations; ++it) {
    shuffle(usable, shuffle_rng);
    TrainingProgress p;
    p.restart = restart;
    p.iteration = it;
    p.iterations = config.iterations;
    train_one_pass(net, optimizer, generator, train_steps, fixed, usable, p);
    if (!std::isfinite(p.loss))
      throw InputError("compile training", "loss became non-finite at iteration " + std::to_string(it) +
                                               " (learning rate too high or data not normalised?)");
    summary.iterations_run = it;
    summary.final_loss = p.loss;
    const bool check = !valid_batches.empty() && (it % config.eval_interval == 0 || it == config.iterations);
    if (check) {
      p.valid_nll = validation_nll(net, valid_batches);
      if (!(p.valid_nll >= summary.best_valid_nll)) {  // also true while best is NaN
        summary.best_valid_nll = p.valid_nll;
        summary.best_iteration = it;
        best.clear();
        for (const auto& t : params) best.push_back(t.detach().clone());
        checks_without_improvement = 0;
        p.improved = true;
      } else {
        ++checks_without_improvement;
      }
    }
    p.best_valid_nll = summary.best_valid_nll;
    p.elapsed_seconds = elapsed();
    p.phase_start_seconds = phase_start;
    report(p);
    if (checks_without_improvement >= config.patience) {
      summary.stopped_early = true;
      break;
    }
  }
  if (!best.empty()) {
    torch::NoGradGuard no_grad;
    for (std::size_t i = 0; i < params.size(); ++i) params[i].copy_(best[i]);
  } else {
    summary.best_iteration = summary.iterations_run;
  }
  summary.warm_start_valid_nll = warm_valid_nll;
  summary.seconds = elapsed();
  return out;
}

}  // namespace

CompileModel CompileTrainer::train(const std::vector<StepSequence>& train, const std::vector<StepSequence>& valid,
                                   const ProgressCallback& progress) {
  configure_torch_threads();
  config_.validate("compile config");
  if (train.empty()) throw InputError("training data", "no trajectories");
  const auto train_steps = to_model_inputs(train, config_, "training trajectory");
  const auto valid_steps = to_model_inputs(valid, config_, "validation trajectory");
  std::vector<std::size_t> usable;
  for (std::size_t i = 0; i < train_steps.size(); ++i)
    if (train_steps[i].steps.length() > 0) usable.push_back(i);
  if (usable.empty()) throw InputError("training data", "every trajectory is empty");
  FixedPositions fixed_train, fixed_valid;
  if (fixed_) {
    fixed_train =
        to_fixed_positions(fixed_train_, train_steps, config_.num_segments, "fixed boundaries of training trajectory");
    fixed_valid = to_fixed_positions(fixed_valid_, valid_steps, config_.num_segments,
                                     "fixed boundaries of validation trajectory");
  }
  const std::vector<Batch> valid_batches = fixed_batches(valid_steps, fixed_valid, config_);
  FixedPositions warm;
  SegmentUnits warm_units;
  double warm_count = std::numeric_limits<double>::quiet_NaN();
  if (config_.warm_start_iterations > 0 && !fixed_) {
    RepeatBoundaryConfig repeat;
    repeat.max_boundaries = std::max(0, config_.num_segments - 1);
    if (warm_given_set_ && warm_given_.size() != train.size())
      throw InputError("warm-start boundaries", std::to_string(warm_given_.size()) + " lists for " +
                                                    std::to_string(train.size()) + " training trajectories");
    const auto found = warm_given_set_ ? warm_given_ : find_repeat_boundaries(train, repeat);
    warm = to_fixed_positions(found, train_steps, config_.num_segments, "warm-start boundaries of training trajectory");
    if (config_.warm_start_units) {
      const auto units =
          warm_units_given_.empty() ? repeat_units(train, found, config_.latent_size) : warm_units_given_;
      warm_units = to_segment_units(units, found, warm, config_.latent_size, "warm-start units of training trajectory");
    }
    std::size_t total = 0;
    for (const auto& f : found) total += f.size();
    warm_count = static_cast<double>(total) / static_cast<double>(found.size());
  }
  const RunData run_data{train_steps, fixed_train, warm, warm_units, valid_batches};

  const auto start_time = std::chrono::steady_clock::now();
  std::mutex report_mutex;
  auto report = [&](TrainingProgress& p) {
    p.restarts = config_.restarts;
    const std::lock_guard<std::mutex> lock(report_mutex);
    if (progress) progress(p);
  };
  std::vector<RunResult> runs(static_cast<std::size_t>(config_.restarts));
  std::vector<std::exception_ptr> errors(runs.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t r; (r = next++) < runs.size();) {
      try {
        runs[r] = train_run(config_, config_.seed + r, static_cast<int>(r), run_data, usable, report);
      } catch (...) {
        errors[r] = std::current_exception();
      }
    }
  };
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> threads;
  for (std::size_t i = 1; i < std::min(cores, runs.size()); ++i) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);

  std::vector<CompileModel> models;
  std::vector<RestartOutcome> outcomes;
  for (RunResult& run : runs) {
    models.emplace_back(std::move(run.impl));
    outcomes.push_back({run.summary.best_valid_nll, run.summary.warm_start_unit_term});
    if (review_) outcomes.back().score = review_(models.back(), static_cast<int>(models.size() - 1));
  }
  const std::size_t kept = choose_restart(outcomes);
  summary_ = runs[kept].summary;
  summary_.restart = static_cast<int>(kept);
  summary_.warm_start_boundaries = warm_count;
  for (const RestartOutcome& run : outcomes) {
    summary_.restart_valid_nll.push_back(run.valid_nll);
    summary_.restart_unit_term.push_back(run.unit_term);
    if (review_) summary_.restart_score.push_back(run.score);
  }
  summary_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return std::move(models[kept]);
}

}  // namespace sc
