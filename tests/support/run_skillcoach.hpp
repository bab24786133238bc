#pragma once
// Runs the built `skillcoach` program ($SKILLCOACH_BINARY) the way a user would, for the CLI and
// screenshot tests.
#include <string>
#include <string_view>

namespace sc::test {

struct CommandResult {
  int exit_code = -1;  // the exit status, or 128 + signal when the program was killed
  std::string output;  // stdout and stderr, interleaved
};

// $SKILLCOACH_BINARY; throws std::runtime_error when the variable is unset.
std::string skillcoach_binary();
// `env_prefix` is prepended to the command line (e.g. "SKILLCOACH_GL=egl"), then $SKILLCOACH_PROGRAM_ENV
// when set (variable assignments for the program only: the `asan` test preset keeps Mesa's GL driver
// loaded in the program so LeakSanitizer can name it, docs/hardening.md); arguments are passed to the
// shell as given, so quote paths that may contain spaces.
CommandResult run_skillcoach(std::string_view arguments, std::string_view env_prefix = {});

}  // namespace sc::test
