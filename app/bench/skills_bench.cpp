// Benchmarks of CompILE: training-iteration time at the paper's parking and writing configs and
// inference latency, on synthetic data shaped like the real tasks (lengths, dimensions). The reference
// (authors' PyTorch code, same kind of machine, reference-baseline.md): parking 141-156 ms per iteration
// (50 trajectories, T <= 29), writing 415 s per batch of 50 words, segmenting one 29-step parking
// trajectory 13.5 ms. Torch runs on one thread and OpenBLAS on one thread (configure_torch_threads).
#include <benchmark/benchmark.h>

#include "teaching/skills/compile_extractor.hpp"
#include "teaching/skills/compile_trainer.hpp"
#include "teaching/skills/synthetic_sequences.hpp"

namespace {

std::vector<sc::StepSequence> steps_of(const std::vector<sc::PlantedSequence>& planted) {
  std::vector<sc::StepSequence> out;
  for (const auto& p : planted) out.push_back(p.steps);
  return out;
}

// Trains `iterations` iterations and reports the mean time of iterations 2..n (manual time), so network
// construction, data conversion and first-touch allocation are not counted.
void time_training(benchmark::State& state, const sc::CompileConfig& base, const std::vector<sc::StepSequence>& data,
                   int iterations) {
  sc::CompileConfig config = base;
  config.iterations = iterations;
  for (auto _ : state) {
    double first = 0.0, last = 0.0;
    sc::CompileTrainer(config).train(data, {}, [&](const sc::TrainingProgress& p) {
      if (p.iteration == 1) first = p.elapsed_seconds;
      last = p.elapsed_seconds;
    });
    state.SetIterationTime((last - first) / (iterations - 1));
  }
}

// Parking config (latent 16, K 4, statediff+action, batch 100): 50 trajectories, T in [11, max_t] -> one
// batch per iteration, as in the reference measurement.
void BM_CompileParkingTrainingIteration(benchmark::State& state) {
  const int max_t = static_cast<int>(state.range(0));
  time_training(state, sc::CompileConfig::parking_defaults(), steps_of(sc::parking_like_sequences(50, 11, max_t, 1)),
                11);
}
BENCHMARK(BM_CompileParkingTrainingIteration)
    ->Arg(29)
    ->Arg(57)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

// Writing config (latent 24, K 8, action mode, 5-px resampling): one batch of 50 words of ~1000-2700 1-px
// steps (the reference: 415 s for one such batch).
void BM_CompileWritingTrainingBatch(benchmark::State& state) {
  time_training(state, sc::CompileConfig::writing_defaults(), steps_of(sc::writing_like_sequences(50, 8, 2)), 4);
}
BENCHMARK(BM_CompileWritingTrainingBatch)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);

// Inference: segmenting a learner's pre-test of 5 trajectories in one call (argmax, no autograd).
void segment_five(benchmark::State& state, const sc::CompileConfig& base, const std::vector<sc::StepSequence>& five) {
  sc::CompileConfig config = base;
  // No ordinary training; the writing defaults' warm start still runs, and its weights matter: the hard
  // readout's passes follow the boundaries the weights give (measured: untrained writing weights segment the
  // five words in 5.7 ms, warm-started ones in 14.5 ms; docs/skills.md, "Speed").
  config.iterations = 0;
  const sc::CompileExtractor extractor(
      std::make_shared<const sc::CompileModel>(sc::CompileTrainer(config).train(five, {})));
  for (auto _ : state) benchmark::DoNotOptimize(extractor.extract_all(five));
}
void BM_CompileSegmentFiveParking(benchmark::State& state) {
  segment_five(state, sc::CompileConfig::parking_defaults(), steps_of(sc::parking_like_sequences(5, 29, 29, 3)));
}
BENCHMARK(BM_CompileSegmentFiveParking)->Unit(benchmark::kMillisecond);
void BM_CompileSegmentFiveWriting(benchmark::State& state) {
  segment_five(state, sc::CompileConfig::writing_defaults(), steps_of(sc::writing_like_sequences(5, 8, 4)));
}
BENCHMARK(BM_CompileSegmentFiveWriting)->Unit(benchmark::kMillisecond);

}  // namespace
