#include "teaching/tasks/writing_realistic_learner.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/error.hpp"
#include "engine/writing/stroke_file.hpp"
#include "engine/writing/word_trajectory.hpp"

namespace sc {
namespace {

constexpr std::string_view kClassicCharacters = "abcte";
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The classic canvas has no pen lifts, so a drawer's strokes are written as one.
writing::StrokeDrawing joined_strokes(const writing::StrokeDrawing& drawing) {
  writing::StrokeDrawing out;
  out.strokes.emplace_back();
  for (const writing::Stroke& s : drawing.strokes)
    out.strokes.front().insert(out.strokes.front().end(), s.begin(), s.end());
  return out;
}

std::vector<writing::TracePoint> chained(const std::vector<writing::WritingStep>& steps) {
  std::vector<writing::TracePoint> pts;
  pts.reserve(steps.size() + 1);
  double x = writing::kStartX, y = writing::kStartY;
  pts.push_back({x, y, steps.empty() ? true : steps.front().pen});
  for (const auto& s : steps) {
    x += s.dx;
    y += s.dy;
    pts.push_back({x, y, s.pen});
  }
  return pts;
}

std::vector<double> arc_lengths(const std::vector<writing::TracePoint>& pts) {
  std::vector<double> s(pts.size(), 0.0);
  for (std::size_t i = 1; i < pts.size(); ++i)
    s[i] = s[i - 1] + std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
  return s;
}

// A smooth function of path length: three sinusoids, slow to fast, weights summing to 1.
struct SmoothCurve {
  double wavelength[3];
  double phase[3];
  static SmoothCurve draw(Rng& rng) {
    SmoothCurve c{};
    const double lo[3] = {150.0, 60.0, 30.0}, hi[3] = {300.0, 150.0, 60.0};
    for (int j = 0; j < 3; ++j) {
      c.wavelength[j] = rng.uniform(lo[j], hi[j]);
      c.phase[j] = rng.uniform(0.0, kTwoPi);
    }
    return c;
  }
  double at(double s) const {
    constexpr double weight[3] = {0.6, 0.3, 0.1};
    double v = 0.0;
    for (int j = 0; j < 3; ++j) v += weight[j] * std::sin(kTwoPi * s / wavelength[j] + phase[j]);
    return v;
  }
};

writing::TracePoint point_at(const std::vector<writing::TracePoint>& pts, const std::vector<double>& s, double at) {
  const auto it = std::upper_bound(s.begin(), s.end(), at);
  if (it == s.begin()) return pts.front();
  if (it == s.end()) return pts.back();
  const std::size_t i = static_cast<std::size_t>(it - s.begin());  // s[i - 1] <= at < s[i]
  const double f = (at - s[i - 1]) / (s[i] - s[i - 1]);
  return {pts[i - 1].x + f * (pts[i].x - pts[i - 1].x), pts[i - 1].y + f * (pts[i].y - pts[i - 1].y), pts[i].pen};
}

}  // namespace

std::vector<int> training_drawers() {
  std::vector<int> out;
  for (int d = 1; d < kFirstUnseenDrawer; ++d) out.push_back(d);
  return out;
}

std::vector<int> unseen_drawers() {
  std::vector<int> out;
  for (int d = kFirstUnseenDrawer; d <= writing::kDrawersPerCharacter; ++d) out.push_back(d);
  return out;
}

ClassicDrawerGlyphs ClassicDrawerGlyphs::load(const std::filesystem::path& data_dir) {
  ClassicDrawerGlyphs out;
  const writing::GlyphSet paper = writing::GlyphSet::load(writing::AlphabetKind::Classic, data_dir);
  for (char symbol : kClassicCharacters) {
    out.glyphs_[{symbol, 0}] = paper.glyph(symbol);
    const int character = writing::character_number(writing::AlphabetKind::Classic, symbol);
    for (int d = 1; d <= writing::kDrawersPerCharacter; ++d) {
      const std::string name = writing::stroke_file_name(character, d);
      out.glyphs_[{symbol, d}] =
          writing::classic_glyph(symbol, joined_strokes(writing::read_stroke_file(data_dir / name)), name);
    }
  }
  for (char symbol : std::string_view("-^")) out.glyphs_[{symbol, 0}] = writing::connector_glyph(symbol);
  return out;
}

const writing::Glyph& ClassicDrawerGlyphs::glyph(char symbol, int drawer) const {
  const auto it = glyphs_.find({symbol, writing::is_connector(symbol) ? 0 : drawer});
  if (it == glyphs_.end())
    throw InputError("realistic learner",
                     std::string("no glyph for '") + symbol + "' by drawer " + std::to_string(drawer));
  return it->second;
}

std::vector<int> WrittenWord::interior_boundaries() const {
  return symbol_starts.empty() ? std::vector<int>{} : std::vector<int>(symbol_starts.begin() + 1, symbol_starts.end());
}

WrittenWord written_word(const ClassicDrawerGlyphs& glyphs, std::string_view word, const std::vector<int>& drawers) {
  writing::validate_word(writing::AlphabetKind::Classic, word, "realistic learner");
  if (!drawers.empty() && drawers.size() != word.size())
    throw InputError("realistic learner", "one drawer per symbol of '" + std::string(word) + "' expected");
  WrittenWord out{std::string(word), {}, {}};
  std::vector<writing::WritingStep> steps;
  for (std::size_t k = 0; k < word.size(); ++k) {
    out.symbol_starts.push_back(static_cast<int>(steps.size()));
    const writing::Glyph& g = glyphs.glyph(word[k], drawers.empty() ? 0 : drawers[k]);
    steps.insert(steps.end(), g.steps.begin(), g.steps.end());
  }
  out.points = chained(steps);
  return out;
}

WrittenWord perturbed(const WrittenWord& word, const HandNoise& noise, Rng& rng) {
  WrittenWord out = word;
  const std::size_t n = word.points.size();
  if (n < 2) return out;
  // Per-letter affine map of the letter's pen steps, then re-chained: letters stay joined.
  std::vector<writing::WritingStep> steps(n - 1);
  for (std::size_t k = 0; k < word.symbol_starts.size(); ++k) {
    const double a = noise.affine;
    const double sx = 1.0 + rng.uniform(-a, a), sy = 1.0 + rng.uniform(-a, a), shear = rng.uniform(-a, a);
    const double rot = rng.uniform(-a / 2, a / 2), c = std::cos(rot), s = std::sin(rot);
    const std::size_t begin = static_cast<std::size_t>(word.symbol_starts[k]);
    const std::size_t end =
        k + 1 < word.symbol_starts.size() ? static_cast<std::size_t>(word.symbol_starts[k + 1]) : n - 1;
    for (std::size_t i = begin; i < end; ++i) {
      const double dx = word.points[i + 1].x - word.points[i].x, dy = word.points[i + 1].y - word.points[i].y;
      const double ux = sx * dx + shear * dy, uy = sy * dy;  // scale and shear, then rotate
      steps[i] = {c * ux - s * uy, s * ux + c * uy, word.points[i + 1].pen};
    }
  }
  out.points = chained(steps);
  out.points.front().pen = word.points.front().pen;
  const SmoothCurve wx = SmoothCurve::draw(rng), wy = SmoothCurve::draw(rng);
  const std::vector<double> s = arc_lengths(out.points);
  for (std::size_t i = 0; i < n; ++i) {
    out.points[i].x += noise.wobble_px * wx.at(s[i]);
    out.points[i].y += noise.wobble_px * wy.at(s[i]);
  }
  return out;
}

namespace {

// Reads the pen at the mouse's event rate and records what the window system would report.
class MouseRecorder {
 public:
  MouseRecorder(const MouseSampling& mouse, double screen_scale, std::size_t symbols)
      : dt_(1.0 / mouse.events_hz), scale_(screen_scale), starts_(symbols, -1) {}

  void read(const writing::TracePoint& p, int jitter_x = 0, int jitter_y = 0) {
    const writing::TracePoint q{(std::round(p.x * scale_) + jitter_x) / scale_,
                                (std::round(p.y * scale_) + jitter_y) / scale_, p.pen};
    if (out_.trace.points.empty() || q.x != out_.trace.points.back().x || q.y != out_.trace.points.back().y) {
      out_.trace.points.push_back(q);
      out_.trace.times.push_back(t_);
      for (int& start : starts_)
        if (start == -2) start = static_cast<int>(out_.trace.points.size()) - 1;
    }
    t_ += dt_;
  }
  // The next recorded point is the first of symbol k.
  void symbol_begins(std::size_t k) { starts_[k] = -2; }
  void pause(const writing::TracePoint& p, double seconds, Rng& rng) {
    for (double waited = 0.0; waited < seconds; waited += dt_) {
      const bool tremble = rng.uniform() < 0.3;
      read(p, tremble ? static_cast<int>(rng.below(3)) - 1 : 0, tremble ? static_cast<int>(rng.below(3)) - 1 : 0);
    }
  }
  SampledTrace finish() {
    const int last = static_cast<int>(out_.trace.points.size()) - 1;
    for (int& start : starts_)
      if (start < 0) start = last;
    out_.symbol_starts = starts_;
    return std::move(out_);
  }

 private:
  double dt_, scale_, t_ = 0.0;
  std::vector<int> starts_;  // -1 not reached, -2 pending (the next recorded point)
  SampledTrace out_;
};

}  // namespace

SampledTrace mouse_sampled(const WrittenWord& word, const MouseSampling& mouse, Rng& rng) {
  const std::vector<double> s = arc_lengths(word.points);
  const double total = s.empty() ? 0.0 : s.back();
  const std::size_t symbols = word.symbol_starts.size();
  MouseRecorder recorder(mouse, rng.uniform(mouse.screen_scale_min, mouse.screen_scale_max), symbols);
  const double speed = rng.uniform(mouse.speed_min, mouse.speed_max);
  const SmoothCurve pace = SmoothCurve::draw(rng);
  // Where each symbol begins along the path, and where the hand pauses (at that start, or inside the symbol).
  std::vector<double> starts_at(symbols), pause_at(symbols, -1.0);
  for (std::size_t k = 0; k < symbols; ++k) {
    starts_at[k] = s[static_cast<std::size_t>(word.symbol_starts[k])];
    const double end = k + 1 < symbols ? s[static_cast<std::size_t>(word.symbol_starts[k + 1])] : total;
    const double chance = rng.uniform();
    if (chance < mouse.hesitations_per_letter)
      pause_at[k] = starts_at[k];
    else if (chance < mouse.hesitations_per_letter * 1.1)
      pause_at[k] = rng.uniform(starts_at[k], end);
  }
  double at = 0.0;
  std::size_t next_symbol = 0, next_pause = 0;
  while (true) {
    while (next_symbol < symbols && starts_at[next_symbol] <= at) recorder.symbol_begins(next_symbol++);
    const writing::TracePoint p = point_at(word.points, s, at);
    recorder.read(p);
    for (; next_pause < symbols && (pause_at[next_pause] < 0.0 || pause_at[next_pause] <= at); ++next_pause)
      if (pause_at[next_pause] >= 0.0) recorder.pause(p, rng.uniform(0.1, mouse.hesitation_seconds_max), rng);
    if (at >= total) break;
    at = std::min(total, at + speed * (1.0 + 0.6 * pace.at(at)) / mouse.events_hz);
  }
  return recorder.finish();
}

SampledTrace unsampled(const WrittenWord& word) {
  SampledTrace out;
  out.trace.points = word.points;
  for (std::size_t i = 0; i < word.points.size(); ++i) out.trace.times.push_back(static_cast<double>(i) / 100.0);
  out.symbol_starts = word.symbol_starts;
  return out;
}

SampledTrace realistic_trace(const ClassicDrawerGlyphs& glyphs, std::string_view word, const RealisticHand& hand,
                             std::uint64_t seed) {
  const Rng root(seed);
  Rng pick = root.fork(1), shape = root.fork(2), mouse = root.fork(3);
  std::vector<int> drawers;
  if (!hand.drawer_pool.empty())
    for (std::size_t k = 0; k < word.size(); ++k)
      drawers.push_back(hand.drawer_pool[pick.below(hand.drawer_pool.size())]);
  const WrittenWord shaped = perturbed(written_word(glyphs, word, drawers), hand.noise, shape);
  return hand.mouse ? mouse_sampled(shaped, hand.sampling, mouse) : unsampled(shaped);
}

std::vector<int> infilled_symbol_starts(const writing::TimedTrace& trace, const std::vector<int>& symbol_starts) {
  std::vector<int> index(trace.points.size(), 0);
  for (std::size_t i = 0; i + 1 < trace.points.size(); ++i) {
    const std::vector<writing::Point2> pair{{trace.points[i].x, trace.points[i].y},
                                            {trace.points[i + 1].x, trace.points[i + 1].y}};
    index[i + 1] = index[i] + static_cast<int>(writing::infill_reference(pair).size()) - 1;
  }
  std::vector<int> out;
  for (int k : symbol_starts) out.push_back(index.at(static_cast<std::size_t>(k)));
  return out;
}

}  // namespace sc
