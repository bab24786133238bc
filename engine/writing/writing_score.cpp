#include "engine/writing/writing_score.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/writing/point_grid.hpp"

namespace sc::writing {
namespace {

double total_ink_length(const std::vector<TracePoint>& trace) {
  double total = 0.0;
  for (std::size_t i = 1; i < trace.size(); ++i)
    if (trace[i].pen) total += std::hypot(trace[i].x - trace[i - 1].x, trace[i].y - trace[i - 1].y);
  return total;
}

double credit(double d, const WritingScoreParams& p) {
  if (d <= p.tolerance_px) return 1.0;
  if (d >= p.cutoff_px) return 0.0;
  return (p.cutoff_px - d) / (p.cutoff_px - p.tolerance_px);
}

double mean_credit(const std::vector<Point2>& queries, const PointGrid& targets, const WritingScoreParams& p) {
  if (queries.empty()) return 0.0;
  double sum = 0.0;
  for (const auto& q : queries) sum += credit(targets.nearest(q, p.tolerance_px), p);
  return sum / static_cast<double>(queries.size());
}

}  // namespace

std::vector<Point2> resample_ink(const std::vector<TracePoint>& trace, double spacing, double* ink_length) {
  std::vector<Point2> out;
  double total = 0.0;
  bool in_run = false;
  double since_sample = 0.0;  // arc length from the last emitted sample to the current point
  auto close_run = [&](const TracePoint& end) {
    if (in_run && since_sample > 1e-9) out.push_back({end.x, end.y});
    in_run = false;
  };
  for (std::size_t i = 1; i < trace.size(); ++i) {
    const TracePoint& a = trace[i - 1];
    const TracePoint& b = trace[i];
    if (!b.pen) {
      close_run(a);
      continue;
    }
    if (!in_run) {
      out.push_back({a.x, a.y});
      in_run = true;
      since_sample = 0.0;
    }
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    total += len;
    double s = spacing - since_sample;  // position of the next sample along this segment
    while (s <= len) {
      out.push_back({a.x + (b.x - a.x) * (s / len), a.y + (b.y - a.y) * (s / len)});
      s += spacing;
    }
    since_sample = len - (s - spacing);
  }
  if (!trace.empty()) close_run(trace.back());
  if (ink_length != nullptr) *ink_length = total;
  return out;
}

WritingScore score_writing(const std::vector<TracePoint>& gold, const std::vector<TracePoint>& learner,
                           const WritingScoreParams& params) {
  if (!(params.tolerance_px >= 0.0) || !(params.cutoff_px > params.tolerance_px) || !(params.spacing_px > 0.0))
    throw std::invalid_argument("score_writing: need 0 <= tolerance < cutoff and spacing > 0");
  auto spacing_for = [&](const std::vector<TracePoint>& trace) {
    const double length = total_ink_length(trace);
    return std::max(params.spacing_px, length / static_cast<double>(std::max<std::size_t>(params.max_samples, 1)));
  };
  WritingScore s;
  const auto gold_ink = resample_ink(gold, spacing_for(gold), &s.gold_ink_px);
  const auto learner_ink = resample_ink(learner, spacing_for(learner), &s.learner_ink_px);
  if (gold_ink.empty()) throw std::invalid_argument("score_writing: the gold trajectory has no ink");
  s.gold_samples = gold_ink.size();
  s.learner_samples = learner_ink.size();
  const PointGrid gold_grid(gold_ink, params.cutoff_px);
  const PointGrid learner_grid(learner_ink, params.cutoff_px);
  s.recall = mean_credit(gold_ink, learner_grid, params);
  s.precision = mean_credit(learner_ink, gold_grid, params);
  s.f_measure = s.recall + s.precision > 0.0 ? 2.0 * s.recall * s.precision / (s.recall + s.precision) : 0.0;
  s.score = s.recall * s.precision - 1.0;
  return s;
}

Json writing_score_json(const WritingScore& score, const WritingScoreParams& params) {
  return Json{{"score", score.score},
              {"recall", score.recall},
              {"precision", score.precision},
              {"f_measure", score.f_measure},
              {"gold_ink_px", score.gold_ink_px},
              {"learner_ink_px", score.learner_ink_px},
              {"gold_samples", score.gold_samples},
              {"learner_samples", score.learner_samples},
              {"tolerance_px", params.tolerance_px},
              {"cutoff_px", params.cutoff_px},
              {"spacing_px", params.spacing_px}};
}

}  // namespace sc::writing
