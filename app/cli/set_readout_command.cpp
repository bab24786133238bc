// skillcoach set-readout --model FILE --phases P: how many phases of its resampling a CompILE model reads
// when it segments (CompileConfig::readout_phases, teaching/skills/phase_vote.hpp). Inference only: the
// weights, the training data and metrics in the sidecar are kept; the model file and the sidecar's config
// are rewritten. Why a command: models trained before the phase vote read one phase, and a researcher's
// own model should not change behaviour unless asked. A model that does not resample is refused.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "teaching/skills/compile_config.hpp"
#include "teaching/skills/compile_model.hpp"

namespace sc::cli {
namespace {

struct SetReadoutArgs {
  std::string model;
  int phases = 1;
};

int run(const SetReadoutArgs& args) {
  CompileModel model = CompileModel::load(args.model);
  if (model.config().resample_step <= 0.0)
    throw InputError(args.model, "model does not resample (resample_step 0): it has one reading only");
  const int before = model.config().readout_phases;
  model.set_readout_phases(args.phases);
  const std::filesystem::path sidecar_path = model_sidecar_path(args.model);
  Json sidecar = read_json_file(sidecar_path);
  if (!sidecar.is_object()) throw InputError(sidecar_path.string(), "not a JSON object");
  // One write of each file: the sidecar keeps its record (metrics, noise floor, ...) with the new config.
  ModelProvenance provenance;
  if (sidecar.contains("data") && sidecar["data"].is_string()) provenance.data_description = sidecar["data"];
  if (sidecar.contains("git_revision") && sidecar["git_revision"].is_string())
    provenance.git_revision = sidecar["git_revision"];
  if (sidecar.contains("metrics") && sidecar["metrics"].is_object()) provenance.metrics = sidecar["metrics"];
  provenance.extra = sidecar;
  model.save(args.model, provenance);
  std::printf("%s: reads %d phase%s (was %d)\n", args.model.c_str(), args.phases, args.phases == 1 ? "" : "s", before);
  if (before != args.phases && sidecar.contains("execution_noise_floor"))
    std::printf(
        "its recorded noise floor was calibrated with the old reading: recalibrate it with\n"
        "  skillcoach evaluate-skills --task %s --model %s --noise-floor --learners 200 --seed 0 --record\n",
        model.config().task.c_str(), args.model.c_str());
  return 0;
}

CommandRunner setup_set_readout(CLI::App& sub) {
  auto args = std::make_shared<SetReadoutArgs>();
  sub.add_option("--model", args->model, "CompILE model file (rewritten in place, with its sidecar)")->required();
  sub.add_option("--phases", args->phases,
                 "Phases of the resampling to read and vote over (1 = one reading; writing models trained since "
                 "2026-12-05 read 3)")
      ->required()
      ->check(CLI::Range(1, 16));
  return [args] { return run(*args); };
}

const CommandRegistration kSetReadoutCommandRegistration{
    {"set-readout", "Set how many phases of its resampling a CompILE model reads when it segments",
     "skillcoach set-readout --model assets/models/writing.pt --phases 3", setup_set_readout}};

}  // namespace
}  // namespace sc::cli
