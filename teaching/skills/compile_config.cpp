#include "teaching/skills/compile_config.hpp"

#include <cmath>

#include "engine/core/error.hpp"

namespace sc {

std::string to_string(CompileMode mode) {
  switch (mode) {
    case CompileMode::Action:
      return "action";
    case CompileMode::StateAction:
      return "state+action";
    case CompileMode::StateDiffAction:
      return "statediff+action";
  }
  return "action";
}

CompileMode parse_compile_mode(const std::string& text, const std::string& where) {
  if (text == "action") return CompileMode::Action;
  if (text == "state+action") return CompileMode::StateAction;
  if (text == "statediff+action") return CompileMode::StateDiffAction;
  throw InputError(where, "unknown CompILE mode \"" + text + "\" (expected action, state+action or statediff+action)");
}

CompileConfig CompileConfig::parking_defaults() {
  CompileConfig c;
  c.task = "parking";
  c.mode = CompileMode::StateDiffAction;
  c.state_dim = 12;
  c.action_dim = 2;
  c.latent_size = 16;
  c.num_segments = 4;
  c.prior_rate = 10.0;
  c.beta_s = 1.0;
  c.learning_rate = 1e-3;
  c.batch_size = 100;
  c.iterations = 2000;
  return c;
}

CompileConfig CompileConfig::writing_defaults() {
  CompileConfig c;
  c.task = "writing";
  c.mode = CompileMode::Action;
  c.state_dim = 0;
  c.action_dim = 2;
  c.latent_size = 24;
  c.num_segments = 8;
  c.beta_s = 0.0;
  c.batch_size = 50;
  // Why each value differs from the paper's, with the measurements: docs/skills.md, "Writing model".
  // 1-px pen steps are far more steps than segmentation needs: one model step per 8 px of path, and the
  // reference's mean segment (~250 px) in those steps.
  c.resample_step = 8.0;
  c.readout_phases = 3;
  c.prior_rate = 30.0;
  // From random weights CompILE cuts letters into strokes: start from where the words stop repeating.
  // The paper's learning rate and latent KL keep the latent posterior uniform on our data.
  c.learning_rate = 1e-3;
  c.beta_z = 0.0;
  c.warm_start_iterations = 60;
  c.restarts = 2;  // the warm start depends on the seed: one run per core, the better kept
  c.iterations = 10;
  c.eval_interval = 2;
  c.patience = 10;
  return c;
}

CompileConfig CompileConfig::defaults_for(TaskKind task) {
  return task == TaskKind::parking ? parking_defaults() : writing_defaults();
}

CompileConfig CompileConfig::defaults_for(const std::string& task) {
  return defaults_for(parse_task_kind(task, "--task"));
}

void CompileConfig::validate(const std::string& where) const {
  auto need = [&](bool ok, const std::string& what) {
    if (!ok) throw InputError(where, what);
  };
  need(!task.empty(), "task name is empty");
  need(action_dim >= 1 && action_dim <= 64, "action_dim must be in 1..64");
  need(state_dim >= 0 && state_dim <= 256, "state_dim must be in 0..256");
  need(!uses_states() || state_dim > 0, "mode " + to_string(mode) + " needs states (state_dim > 0)");
  need(latent_size >= 1 && latent_size <= 256, "latent_size must be in 1..256");
  need(num_segments >= 1 && num_segments <= 64, "num_segments must be in 1..64");
  need(hidden >= 2 && hidden <= 1024 && hidden % 2 == 0, "hidden must be an even number in 2..1024");
  need(prior_rate > 0.0, "prior_rate must be positive");
  need(beta_b >= 0.0 && beta_z >= 0.0 && beta_s >= 0.0 && beta_usage >= 0.0,
       "beta_b, beta_z, beta_s and beta_usage must be >= 0");
  need(learning_rate > 0.0 && learning_rate < 1.0, "learning_rate must be in (0, 1)");
  need(batch_size >= 1, "batch_size must be >= 1");
  need(iterations >= 0, "iterations must be >= 0");
  need(eval_interval >= 1, "eval_interval must be >= 1");
  need(patience >= 1, "patience must be >= 1");
  need(restarts >= 1 && restarts <= 64, "restarts must be in 1..64");
  need(resample_step >= 0.0, "resample_step must be >= 0");
  need(readout_phases >= 1 && readout_phases <= 16, "readout_phases must be in 1..16");
  need(warm_start_iterations >= 0, "warm_start_iterations must be >= 0");
  need(warm_start_learning_rate >= 0.0 && warm_start_learning_rate < 1.0, "warm_start_learning_rate must be in [0, 1)");
  need(!warm_start_units || warm_start_iterations > 0, "warm_start_units needs warm_start_iterations > 0");
  need(warm_start_unit_weight >= 0.0 && std::isfinite(warm_start_unit_weight),
       "warm_start_unit_weight must be a finite number >= 0");
  need(encoder_reads_actions || uses_states(), "encoder_reads_actions=false needs a mode with states");
}

Json to_json(const CompileConfig& c, bool every_field) {
  Json out{{"task", c.task},
           {"mode", to_string(c.mode)},
           {"state_dim", c.state_dim},
           {"action_dim", c.action_dim},
           {"latent_size", c.latent_size},
           {"num_segments", c.num_segments},
           {"hidden", c.hidden},
           {"prior_rate", c.prior_rate},
           {"beta_b", c.beta_b},
           {"beta_z", c.beta_z},
           {"beta_s", c.beta_s},
           {"learning_rate", c.learning_rate},
           {"batch_size", c.batch_size},
           {"iterations", c.iterations},
           {"eval_interval", c.eval_interval},
           {"patience", c.patience},
           {"seed", c.seed},
           {"restarts", c.restarts},
           {"resample_step", c.resample_step},
           {"warm_start_iterations", c.warm_start_iterations},
           {"warm_start_learning_rate", c.warm_start_learning_rate},
           {"straight_through_latents", c.straight_through_latents},
           {"warm_start_units", c.warm_start_units},
           {"warm_start_unit_weight", c.warm_start_unit_weight},
           {"beta_usage", c.beta_usage}};
  if (every_field || !c.encoder_reads_actions) out["encoder_reads_actions"] = c.encoder_reads_actions;
  if (every_field || c.readout_phases != 1) out["readout_phases"] = c.readout_phases;
  return out;
}

CompileConfig compile_config_from_json(const JsonView& v) {
  CompileConfig c;
  auto as_int = [&](const char* key) { return static_cast<int>(v.at(key).integer()); };
  c.task = v.at("task").string();
  const JsonView mode = v.at("mode");
  try {
    c.mode = parse_compile_mode(mode.string(), "mode");
  } catch (const InputError&) {
    mode.fail("unknown CompILE mode \"" + mode.string() + "\" (expected action, state+action or statediff+action)");
  }
  c.state_dim = as_int("state_dim");
  c.action_dim = as_int("action_dim");
  c.latent_size = as_int("latent_size");
  c.num_segments = as_int("num_segments");
  c.hidden = as_int("hidden");
  c.prior_rate = v.at("prior_rate").number();
  c.beta_b = v.at("beta_b").number();
  c.beta_z = v.at("beta_z").number();
  c.beta_s = v.at("beta_s").number();
  c.learning_rate = v.at("learning_rate").number();
  c.batch_size = as_int("batch_size");
  c.iterations = as_int("iterations");
  c.eval_interval = as_int("eval_interval");
  c.patience = as_int("patience");
  c.seed = static_cast<std::uint64_t>(v.at("seed").integer());
  c.resample_step = v.at("resample_step").number();
  // Absent in models written before restarts existed (they were single runs).
  if (const auto restarts = v.find("restarts")) c.restarts = static_cast<int>(restarts->integer());
  // Absent in models written before the warm start existed (they trained without one).
  if (const auto warm = v.find("warm_start_iterations")) c.warm_start_iterations = static_cast<int>(warm->integer());
  if (const auto rate = v.find("warm_start_learning_rate")) c.warm_start_learning_rate = rate->number();
  // Absent in models trained on relaxed latents only.
  if (const auto hard = v.find("straight_through_latents")) c.straight_through_latents = hard->boolean();
  if (const auto units = v.find("warm_start_units")) c.warm_start_units = units->boolean();
  if (const auto weight = v.find("warm_start_unit_weight")) c.warm_start_unit_weight = weight->number();
  if (const auto usage = v.find("beta_usage")) c.beta_usage = usage->number();
  if (const auto reads = v.find("encoder_reads_actions")) c.encoder_reads_actions = reads->boolean();
  // Absent in models written before the phase vote (they read one phase).
  if (const auto phases = v.find("readout_phases")) c.readout_phases = static_cast<int>(phases->integer());
  return c;
}

}  // namespace sc
