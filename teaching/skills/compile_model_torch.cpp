// CompileModel: inference, reconstruction error and model files (see compile_model.hpp).
#include <dlfcn.h>

#include <cmath>

#include "engine/core/error.hpp"
#include "teaching/skills/compile_torch.hpp"
#include "teaching/skills/model_file.hpp"
#include "teaching/skills/phase_vote.hpp"

namespace sc {

using compile_detail::Batch;
using compile_detail::make_batch;

namespace {
constexpr const char* kFormatName = "skillcoach-compile";
// Inference batches are bounded so a huge request cannot exhaust memory.
constexpr std::size_t kMaxBatch = 256;
}  // namespace

void configure_torch_threads() {
  at::set_num_threads(1);
  using SetThreads = void (*)(int);
  if (auto* fn = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) fn(1);
}

std::filesystem::path model_sidecar_path(const std::filesystem::path& file) {
  auto p = file;
  p += ".json";
  return p;
}

std::vector<ModelSteps> to_model_inputs(const std::vector<StepSequence>& trajectories, const CompileConfig& config,
                                        const std::string& what, double phase) {
  std::vector<ModelSteps> out;
  out.reserve(trajectories.size());
  for (std::size_t i = 0; i < trajectories.size(); ++i) {
    const StepSequence& s = trajectories[i];
    const std::string where = what + " " + std::to_string(i);
    if (s.action_dim != config.action_dim)
      throw InputError(where, "has " + std::to_string(s.action_dim) + "-D actions, the model expects " +
                                  std::to_string(config.action_dim));
    if (s.actions.size() % static_cast<std::size_t>(s.action_dim) != 0)
      throw InputError(where, "action array is not a whole number of steps");
    if (config.uses_states()) {
      if (s.state_dim != config.state_dim)
        throw InputError(where, "has " + std::to_string(s.state_dim) + "-D states, the model expects " +
                                    std::to_string(config.state_dim));
      if (s.states.size() != static_cast<std::size_t>(s.length() * s.state_dim))
        throw InputError(where, "has " + std::to_string(s.states.size() / static_cast<std::size_t>(s.state_dim)) +
                                    " states for " + std::to_string(s.length()) + " actions");
    }
    for (float v : s.actions)
      if (!std::isfinite(v)) throw InputError(where, "contains a non-finite action");
    out.push_back(to_model_steps(s, config.resample_step, phase));
    if (!config.uses_states()) {  // states are not read in action mode; do not carry them around
      out.back().steps.states.clear();
      out.back().steps.state_dim = 0;
    }
  }
  return out;
}

CompileModel::CompileModel(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
CompileModel::CompileModel(CompileModel&&) noexcept = default;
CompileModel& CompileModel::operator=(CompileModel&&) noexcept = default;
CompileModel::~CompileModel() = default;

const CompileConfig& CompileModel::config() const { return impl_->net.config; }

int CompileModel::parameter_count() const {
  std::int64_t n = 0;
  for (auto& [name, t] : impl_->net.named()) n += t->numel();
  return static_cast<int>(n);
}

namespace {

// Segments model inputs in the trajectories' own action indices (an empty input gives no segments).
std::vector<Segmentation> segment_inputs(const compile_detail::CompileNetwork& net,
                                         const std::vector<ModelSteps>& inputs) {
  std::vector<Segmentation> out(inputs.size());
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (inputs[i].steps.length() > 0) pending.push_back(i);
  for (std::size_t first = 0; first < pending.size(); first += kMaxBatch) {
    const std::size_t last = std::min(pending.size(), first + kMaxBatch);
    std::vector<const StepSequence*> chunk;
    for (std::size_t i = first; i < last; ++i) chunk.push_back(&inputs[pending[i]].steps);
    const Batch batch = make_batch(chunk, net.config);
    const auto readout = compile_detail::hard_readout(net, batch);
    for (std::size_t i = first; i < last; ++i) {
      const ModelSteps& m = inputs[pending[i]];
      const Segmentation model_segments =
          segments_from_boundaries(readout.boundaries[i - first], readout.skills[i - first], m.steps.length());
      out[pending[i]] = to_original_indices(model_segments, m);
    }
  }
  return out;
}

}  // namespace

std::vector<Segmentation> CompileModel::segment(const std::vector<StepSequence>& trajectories) const {
  torch::NoGradGuard no_grad;
  const CompileConfig& c = config();
  const int phases = c.resample_step > 0.0 ? c.readout_phases : 1;
  std::vector<ModelSteps> inputs;  // phase-major: phase p of trajectory i is inputs[p * n + i]
  for (int p = 0; p < phases; ++p)
    for (ModelSteps& m : to_model_inputs(trajectories, c, "trajectory", c.resample_step * p / phases))
      inputs.push_back(std::move(m));
  std::vector<Segmentation> read = segment_inputs(impl_->net, inputs);
  if (phases == 1) return read;
  const std::size_t n = trajectories.size();
  std::vector<Segmentation> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<Segmentation> votes;
    for (int p = 0; p < phases; ++p) votes.push_back(std::move(read[static_cast<std::size_t>(p) * n + i]));
    const int length = trajectories[i].length();
    out[i] = vote_phases(votes, length, phase_vote_tolerance(length, inputs[i].steps.length()));
  }
  return out;
}

void CompileModel::set_readout_phases(int phases) {
  CompileConfig c = impl_->net.config;
  c.readout_phases = phases;
  c.validate("readout phases");
  impl_->net.config = c;
}

double CompileModel::action_reconstruction_error(const std::vector<StepSequence>& trajectories) const {
  torch::NoGradGuard no_grad;
  const auto inputs = to_model_inputs(trajectories, config(), "trajectory");
  double sum = 0.0;
  std::int64_t steps = 0;
  for (std::size_t first = 0; first < inputs.size(); first += kMaxBatch) {
    std::vector<const StepSequence*> chunk;
    for (std::size_t i = first; i < std::min(inputs.size(), first + kMaxBatch); ++i)
      if (inputs[i].steps.length() > 0) chunk.push_back(&inputs[i].steps);
    if (chunk.empty()) continue;
    const Batch batch = make_batch(chunk, config());
    const auto losses = compile_detail::compute_losses(impl_->net, batch, false, nullptr);
    sum += losses.nll_action.item<double>() * static_cast<double>(batch.size);
    for (auto len : batch.lengths) steps += len;
  }
  return steps > 0 ? sum / static_cast<double>(steps * config().action_dim) : 0.0;
}

void CompileModel::save(const std::filesystem::path& file, const ModelProvenance& provenance) const {
  ModelFileContents contents;
  contents.header = Json{{"format", kFormatName}, {"config", to_json(config())}};
  for (auto& [name, t] : impl_->net.named()) {
    const torch::Tensor c = t->detach().contiguous();
    NamedTensor nt;
    nt.name = name;
    nt.shape.assign(c.sizes().begin(), c.sizes().end());
    nt.values.assign(c.data_ptr<float>(), c.data_ptr<float>() + c.numel());
    contents.tensors.push_back(std::move(nt));
  }
  write_model_file(file, contents);
  Json sidecar = provenance.extra.is_object() ? provenance.extra : Json::object();
  sidecar.update(Json{{"format", kFormatName},
                      {"format_version", kModelFormatVersion},
                      {"model_file", file.filename().string()},
                      {"task", config().task},
                      {"config", to_json(config())},
                      {"seed", config().seed},
                      {"parameters", parameter_count()},
                      {"data", provenance.data_description},
                      {"metrics", provenance.metrics},
                      {"git_revision", provenance.git_revision}});
  write_json_file(model_sidecar_path(file), sidecar);
}

CompileModel CompileModel::load(const std::filesystem::path& file, const std::string& expected_task,
                                int expected_state_dim, int expected_action_dim) {
  configure_torch_threads();
  const std::string name = file.string();
  ModelFileContents contents = read_model_file(file);
  const JsonView header(contents.header, name);
  if (!contents.header.is_object() || !contents.header.contains("format") || contents.header["format"] != kFormatName)
    throw InputError(name, "not a CompILE model (header format is not \"" + std::string(kFormatName) + "\")");
  CompileConfig config = compile_config_from_json(header.at("config"));
  config.validate(name + ": $.config");
  if (!expected_task.empty() && config.task != expected_task)
    throw InputError(name, "model was trained for task \"" + config.task + "\", expected \"" + expected_task + "\"");
  if (expected_action_dim >= 0 && config.action_dim != expected_action_dim)
    throw InputError(name, "model expects " + std::to_string(config.action_dim) + "-D actions, the task has " +
                               std::to_string(expected_action_dim));
  if (expected_state_dim >= 0 && config.uses_states() && config.state_dim != expected_state_dim)
    throw InputError(name, "model expects " + std::to_string(config.state_dim) + "-D states, the task has " +
                               std::to_string(expected_state_dim));

  auto gen = at::detail::createCPUGenerator(0);
  auto impl = std::make_unique<CompileModel::Impl>(CompileModel::Impl{compile_detail::CompileNetwork(config, gen)});
  auto named = impl->net.named();
  if (named.size() != contents.tensors.size())
    throw InputError(name, "model has " + std::to_string(contents.tensors.size()) + " tensors, its config needs " +
                               std::to_string(named.size()));
  torch::NoGradGuard no_grad;
  for (std::size_t i = 0; i < named.size(); ++i) {
    const NamedTensor& src = contents.tensors[i];
    torch::Tensor& dst = *named[i].second;
    if (src.name != named[i].first)
      throw InputError(name,
                       "tensor " + std::to_string(i) + " is \"" + src.name + "\", expected \"" + named[i].first + "\"");
    if (std::vector<std::int64_t>(dst.sizes().begin(), dst.sizes().end()) != src.shape)
      throw InputError(name, "tensor \"" + src.name + "\" has the wrong dimensions for the model's config");
    for (float v : src.values)
      if (!std::isfinite(v)) throw InputError(name, "tensor \"" + src.name + "\" contains non-finite values");
    dst.copy_(torch::from_blob(const_cast<float*>(src.values.data()), dst.sizes(), torch::kFloat32));
  }
  return CompileModel(std::move(impl));
}

}  // namespace sc
