#pragma once
// Scratch files for tests: a per-test-group folder under $SKILLCOACH_TEST_OUTPUT (or /tmp), and whole-file
// byte reads/writes for tests that damage files on purpose (truncate, flip bytes) and check they are refused.
#include <filesystem>
#include <string>
#include <string_view>

namespace sc::test {

// <output>/<group>/<name>, creating <output>/<group>.
std::filesystem::path scratch_path(std::string_view group, std::string_view name);
// <output>/<name>, emptied: removed with everything in it and created again.
std::filesystem::path fresh_scratch_dir(std::string_view name);
std::string read_bytes(const std::filesystem::path& file);
// Temporaries of `file` left beside it ("<file>...tmp"; atomic writes must leave none behind). Only that
// file's: tests running in parallel may be writing their own files in the same directory.
int temporaries_left_of(const std::filesystem::path& file);
void write_bytes(const std::filesystem::path& file, std::string_view bytes);

}  // namespace sc::test
