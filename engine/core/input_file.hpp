#pragma once
// Reading a whole input file (trial, model, script, stroke file) the same way everywhere: only a regular
// file is read, so a FIFO cannot block the program and /dev/zero cannot fill memory; a directory says
// "is a directory"; a file larger than the caller's limit is refused before it is read; and a file we may
// not reach (EACCES on it or on a directory above it) is one line, not a filesystem exception.
#include <cstdint>
#include <filesystem>
#include <string>

namespace sc {

// Default limit for JSON documents: the largest the program writes (a writing trial capped at 200,000
// points) is a few MB.
inline constexpr std::uintmax_t kMaxJsonFileBytes = std::uintmax_t{256} << 20;

// The file's bytes; throws InputError("<file>: <problem>") when it is missing, not a regular file,
// larger than `max_bytes`, or unreadable.
std::string read_input_file(const std::filesystem::path& file, std::uintmax_t max_bytes);

}  // namespace sc
