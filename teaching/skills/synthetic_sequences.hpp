#pragma once
// Sequences with planted skill structure, for tests and benchmarks of skill extractors (no task engine
// needed): the true boundaries and primitive ids are known, so segmentation quality can be measured.
#include <cstdint>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

struct PlantedSequence {
  StepSequence steps;
  std::vector<int> boundaries;  // true segment ends (action indices), the last equals the length
  std::vector<int> primitives;  // true primitive id of each segment
};

// Each sequence chains `segments` primitives drawn from `primitive_count` distinct constant actions
// (never the same primitive twice in a row), each held for a random length in [min_length, max_length].
// States (state_dim >= 2) integrate the actions as a position, padded with zeros.
std::vector<PlantedSequence> constant_primitive_sequences(int count, int segments, int primitive_count, int min_length,
                                                          int max_length, int state_dim, std::uint64_t seed);

// Each sequence chains `segments` symbols (never the same twice in a row) from `symbol_count` <= 8 fixed
// symbols: a symbol is a fixed sequence of min_length..max_length (>= 2) unit steps in 16 directions, the
// same steps wherever it occurs (as the writing expert's letters are), with a first and a last step of
// its own. The symbols depend on `symbol_seed` only, so data drawn with other `seed`s share them.
std::vector<PlantedSequence> repeated_symbol_sequences(int count, int segments, int symbol_count, int min_length,
                                                       int max_length, std::uint64_t symbol_seed, std::uint64_t seed);

// Parking-shaped data: 12-D states, 2-D actions in [-1, 1], lengths uniform in [min_length, max_length],
// 2..3 piecewise-smooth manoeuvres per trajectory.
std::vector<PlantedSequence> parking_like_sequences(int count, int min_length, int max_length, std::uint64_t seed);

// Writing-shaped data: words of `symbols` symbols drawn as 1-px pen steps (unit-length actions): curved
// "characters" of 180..420 steps and straight 20-step connectors, T ~ 1000..2700 per 8-symbol word.
std::vector<PlantedSequence> writing_like_sequences(int count, int symbols, std::uint64_t seed);

}  // namespace sc
