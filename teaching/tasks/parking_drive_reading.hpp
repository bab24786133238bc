#pragma once
// How a parking drive is read for its skills: the one place that wraps a skill model for parking, used by the
// parking kit (the trainer, `diagnose`, the evaluations) and by `segment` and `evaluate-skills`, so that all of them
// read a learner's drive alike.
//
// A drive is read from its first to its last moving step (parking_moving_part.hpp), and a moving part much longer
// than the expert pool's longest drive is read in pieces about that long (piecewise_extractor.hpp: why). The time
// heuristic slices whole drives. Expert pool drives move from their first step to their last and are never longer
// than the pool's longest, so they are read exactly as by the model alone.
#include <memory>
#include <vector>

#include "teaching/skills/skill_extractor.hpp"

namespace sc {

// Research switches, to measure what each part of the reading does (`--read-whole-drives`, `--read-in-one-piece`).
struct ParkingDriveReading {
  bool whole_drive = false;  // the reading before 2026-12-05: standing still at the ends included, in one piece
  bool one_piece = false;    // the reading before 2026-12-06: the moving part, in one piece
};

// The longest of the drives' moving parts, in control steps (1 for no drives): the piece length.
int longest_moving_drive(const std::vector<StepSequence>& drives);

// `model` wrapped as described above; `piece_length` from longest_moving_drive of the expert pool.
// InputError for no model or a piece length < 1.
std::shared_ptr<const SkillExtractor> parking_drive_reader(std::shared_ptr<const SkillExtractor> model,
                                                           int piece_length, ParkingDriveReading reading = {});

}  // namespace sc
