#pragma once
// SkillCoach's binary model container (no torch): a JSON header plus named float32 tensors, closed by a
// checksum so truncation and bit rot are detected before any value is used.
//
// Layout (little-endian): "SCMODEL\0" | u32 format version | u32 header length | header JSON |
// u32 tensor count | per tensor: u32 name length, name, u32 rank, i64 dims[rank], f32 values[prod dims] |
// u64 FNV-1a of every byte before it.
// The writer is byte-deterministic (no timestamps), so equal models give equal files.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"

namespace sc {

inline constexpr std::uint32_t kModelFormatVersion = 1;

struct NamedTensor {
  std::string name;
  std::vector<std::int64_t> shape;
  std::vector<float> values;  // row-major, size = product of shape
};

struct ModelFileContents {
  Json header;
  std::vector<NamedTensor> tensors;
};

// Writes atomically (temporary file + rename). Throws InputError if the file cannot be written.
void write_model_file(const std::filesystem::path& file, const ModelFileContents& contents);
// Throws InputError("<file>: <problem>") for a missing, truncated, corrupt, foreign or too-new file.
ModelFileContents read_model_file(const std::filesystem::path& file);

}  // namespace sc
