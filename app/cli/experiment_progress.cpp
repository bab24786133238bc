#include "app/cli/experiment_progress.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace sc::cli {

ExperimentProgress progress_printer() {
  const bool tty = isatty(STDERR_FILENO) != 0;
  const auto start = std::chrono::steady_clock::now();
  return [tty, start](std::string_view phase, int done, int total) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (tty)
      std::fprintf(stderr, "\r\033[K[%6.1f s] %.*s %d/%d%s", seconds, static_cast<int>(phase.size()), phase.data(),
                   done, total, done == total ? "\n" : "");
    else if (done == total)
      std::fprintf(stderr, "[%6.1f s] %.*s done\n", seconds, static_cast<int>(phase.size()), phase.data());
  };
}

}  // namespace sc::cli
