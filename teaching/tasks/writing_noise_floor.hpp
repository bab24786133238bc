#pragma once
// The writing noise floor travels with the model that was calibrated (execution_noise_floor.hpp).
//
// Why: the floor is what realistic noise alone does to a segment's score, and a segment is only what the
// model makes of the expert's word; a floor kept as a constant belongs to one model, and a researcher's own
// model would silently get it. So `train-skills --task writing` calibrates the floor with the model it just
// trained and records it in the model's JSON sidecar, and the kit factory reads it from there.
//
// Spec: the calibration uses the planted table's noise-only learners (noise_only_learner) writing the kit's
// pre-test, kNoiseFloorLearners of them at kNoiseFloorSeed, which no table is reported at. The sidecar holds
// "execution_noise_floor": {"value": f, "percentile": p, "learners": n, "seed": s, "segments": k,
// "repeated_twice": f2, "repeated_more": f3, "skills_twice": n2, "skills_more": n3}; the repeated floors
// (since 2026-12-05) are absent in older records, which then charge no repeated evidence. A model without a
// record (or the time heuristic) has no floor: quality-aware expertise then charges by the learner's own
// outlier cut alone.
#include <cstdint>
#include <filesystem>
#include <optional>

#include "teaching/tasks/execution_noise_floor.hpp"
#include "teaching/tasks/writing_kit.hpp"

namespace sc {

inline constexpr int kNoiseFloorLearners = 200;
inline constexpr std::uint64_t kNoiseFloorSeed = 0;

// `learners` noise-only learners of `seed` writing the kit's pre-test, calibrated with the kit's model.
NoiseFloorCalibration calibrate_writing_noise_floor(const WritingKit& kit, int learners, std::uint64_t seed);

// The floor recorded in `model`'s sidecar; nullopt when there is no sidecar or it records none. Throws
// InputError naming the sidecar when it is not JSON or a floor it records is not a number <= 0.
std::optional<NoiseFloor> recorded_noise_floor(const std::filesystem::path& model);

// Adds (or replaces) the floor in `model`'s sidecar, keeping everything else. Throws InputError when the
// sidecar is missing or unreadable, or cannot be written.
void record_noise_floor(const std::filesystem::path& model, const NoiseFloorCalibration& calibration,
                        std::uint64_t seed);

}  // namespace sc
