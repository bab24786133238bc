#pragma once
// Which of several training runs (CompileConfig::restarts) to keep.
//
// Why: CompILE's relaxed objective has poor local minima, so training runs several restarts and keeps one.
// The validation NLL alone is not enough when the warm start has a unit term (warm_start_units): a restart
// whose warm start ended with two repeated units still on one skill (its unit term left at 2.8-3.4 nats per
// trajectory, against 0.70-0.76 for restarts that separated them) can still have the lower validation NLL -
// one decoder draws both letters well - and was kept once, merging `a` and `b` (docs/skills.md, "Warm-start
// units"). The unit term is evidence from the data's own repetitions, never the true labels.
//
// Spec: a restart is a candidate when its warm start's unit term is within kUnitTermSlack of the lowest
// restart's (every restart is a candidate when the term is NaN for any: no units); among candidates the
// lowest validation NLL is kept, ties and NaN (no validation split) going to the lower index. When every
// candidate has a score (RestartOutcome::score, higher is better: e.g. writing's cross-hand consistency,
// writing_cross_hand.hpp), the highest score is kept instead, ties going to the lower NLL, then the lower index.
// The score only ranks candidates: a restart that merged its units stays out however well it scores (a model
// that gives every step one skill would be perfectly consistent).
#include <cmath>
#include <cstddef>
#include <vector>

namespace sc {

struct RestartOutcome {
  double valid_nll;    // best validation NLL of the run (NaN without a validation split)
  double unit_term;    // unit cross-entropy of the warm start's last pass, per trajectory (NaN: no units)
  double score = NAN;  // the caller's measure of the trained model, higher is better (NaN: not scored)
};

// Less than a merged pair of units costs (2.1-2.7 nats above the separated restarts, measured above).
inline constexpr double kUnitTermSlack = 1.0;

// Index of the run to keep; `runs` must not be empty.
std::size_t choose_restart(const std::vector<RestartOutcome>& runs);

}  // namespace sc
