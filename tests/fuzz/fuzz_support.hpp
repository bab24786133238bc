#pragma once
// Shared by the libFuzzer targets in tests/fuzz/ and by their corpus-replay tests in the normal build.
// Contract of every target: for ANY input the parser either returns a value or throws sc::InputError.
// Any other exception escapes LLVMFuzzerTestOneInput and aborts (libFuzzer reports it as a crash), and
// a broken invariant (e.g. a document that does not read back after writing) calls fuzz_require(),
// which aborts too.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace sc::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Aborts with `what` when `condition` is false: the fuzzer records the input as a crash.
void fuzz_require(bool condition, std::string_view what);

// A scratch directory private to this process (created on first use, under $TMPDIR or /tmp), for
// parsers that only read files. Parsers are fed through real files so the file-opening code is covered.
const std::filesystem::path& scratch_dir();

// Writes `bytes` to `file` (replacing it).
void write_bytes(const std::filesystem::path& file, std::string_view bytes);

}  // namespace sc::fuzz
