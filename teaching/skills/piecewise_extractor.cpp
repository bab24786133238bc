#include "teaching/skills/piecewise_extractor.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "teaching/skills/step_range.hpp"

namespace sc {
namespace {

struct Piece {
  int begin = 0, end = 0;
};

std::vector<Piece> pieces_of(int length, int piece_length) {
  const int n = piece_count(length, piece_length);
  std::vector<Piece> out;
  for (int k = 0; k < n; ++k) {
    const auto begin = static_cast<int>(static_cast<long long>(length) * k / n);
    const auto end = static_cast<int>(static_cast<long long>(length) * (k + 1) / n);
    out.push_back({begin, end});
  }
  return out;
}

}  // namespace

int piece_count(int length, int piece_length) {
  if (piece_length < 1 || length <= 0) return 1;
  return std::max(1, static_cast<int>((2LL * length + piece_length) / (2LL * piece_length)));
}

int shortest_split_length(int piece_length) { return (3 * std::max(1, piece_length) + 1) / 2; }

PiecewiseExtractor::PiecewiseExtractor(std::shared_ptr<const SkillExtractor> inner, int piece_length)
    : inner_(std::move(inner)), piece_length_(piece_length) {
  if (!inner_) throw InputError("piecewise skill extractor", "no extractor to wrap");
  if (piece_length_ < 1) throw InputError("piecewise skill extractor", "the piece length must be >= 1 step");
}

Segmentation PiecewiseExtractor::extract(const StepSequence& trajectory) const {
  if (piece_count(trajectory.length(), piece_length_) == 1) return inner_->extract(trajectory);
  return extract_all({trajectory}).front();
}

std::vector<Segmentation> PiecewiseExtractor::extract_all(const std::vector<StepSequence>& trajectories) const {
  std::vector<StepSequence> pieces;
  std::vector<std::vector<Piece>> places;
  places.reserve(trajectories.size());
  for (const StepSequence& t : trajectories) {
    places.push_back(pieces_of(t.length(), piece_length_));
    if (places.back().size() == 1) {
      pieces.push_back(t);
      continue;
    }
    for (Piece p : places.back()) pieces.push_back(steps_between(t, p.begin, p.end));
  }
  const std::vector<Segmentation> read = inner_->extract_all(pieces);
  std::vector<Segmentation> out(trajectories.size());
  std::size_t next = 0;
  for (std::size_t i = 0; i < trajectories.size(); ++i) {
    for (Piece p : places[i]) {
      for (const SkillSegment& s : shifted(read[next++], p.begin).segments) out[i].segments.push_back(s);
    }
  }
  return out;
}

}  // namespace sc
