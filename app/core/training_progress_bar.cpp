#include "app/core/training_progress_bar.hpp"

#include <unistd.h>

#include <cmath>

namespace sc::cli {
namespace {

std::string format(const char* pattern, double a, double b = 0.0) {
  char text[96];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

std::string duration(double seconds) {
  if (seconds < 120.0) return format("%.0f s", seconds);
  return format("%.0f min %02.0f s", std::floor(seconds / 60.0), std::fmod(seconds, 60.0));
}

}  // namespace

std::string describe_training_progress(const TrainingProgress& p) {
  std::string line;
  if (p.restarts > 1) line = "run " + std::to_string(p.restart + 1) + "/" + std::to_string(p.restarts) + "  ";
  line += (p.warm_start ? "warm start " : "it ") + std::to_string(p.iteration) + "/" + std::to_string(p.iterations);
  line += format("  loss %.4g (nll_a %.4g", p.loss, p.nll_action);
  if (p.nll_state != 0.0) line += format(" nll_s %.4g", p.nll_state);
  line += format(" kl_z %.3g kl_b %.3g", p.kl_z, p.kl_b);
  if (p.warm_start) line += format(" boundary_ce %.3g", p.boundary_ce);
  if (p.warm_start && p.unit_ce != 0.0) line += format(" unit_ce %.3g", p.unit_ce);
  line += ")";
  if (std::isfinite(p.valid_nll)) line += format("  valid %.4g", p.valid_nll) + (p.improved ? " *" : "");
  if (std::isfinite(p.best_valid_nll)) line += format("  best %.4g", p.best_valid_nll);
  line += "  " + duration(p.elapsed_seconds);
  // An upper bound: early stopping may end the run sooner.
  const double phase = p.elapsed_seconds - p.phase_start_seconds;
  const double eta = p.iteration > 0 ? phase / p.iteration * (p.iterations - p.iteration) : 0.0;
  if (p.iteration < p.iterations) line += "  ETA " + duration(eta);
  return line;
}

TrainingProgressBar::TrainingProgressBar(std::FILE* out) : out_(out), terminal_(isatty(fileno(out)) != 0) {}

void TrainingProgressBar::update(const TrainingProgress& p) {
  const std::string line = describe_training_progress(p);
  if (terminal_) {
    const std::size_t pad = last_width_ > line.size() ? last_width_ - line.size() : 0;
    std::fprintf(out_, "\r%s%s", line.c_str(), std::string(pad, ' ').c_str());
    last_width_ = line.size();
    line_open_ = true;
  } else if (std::isfinite(p.valid_nll) || p.iteration == p.iterations || p.iteration == 1) {
    std::fprintf(out_, "%s\n", line.c_str());
  }
  std::fflush(out_);
}

void TrainingProgressBar::finish() {
  if (line_open_) std::fprintf(out_, "\n");
  line_open_ = false;
  std::fflush(out_);
}

}  // namespace sc::cli
