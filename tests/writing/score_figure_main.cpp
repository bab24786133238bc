// writing_score_figure OUT.png: draws the picture in docs/writing-score.md - the gold ink with its credit
// band, and an imperfect learner trace whose ink samples are coloured by the credit they earn - and prints
// the score of that trace. Not a test: a small tool to regenerate the documentation figure.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <stb_image_write.h>

#include "engine/writing/writing_scenario.hpp"
#include "engine/writing/writing_score.hpp"

namespace {

using sc::writing::Point2;
using sc::writing::TracePoint;

struct Rgb {
  unsigned char r, g, b;
};

class Image {
 public:
  Image(int w, int h, double x0, double y0, double zoom)
      : w_(w), h_(h), x0_(x0), y0_(y0), zoom_(zoom), px_(w * h * 3, 255) {}
  void set(int X, int Y, Rgb c, double alpha = 1.0) {
    if (X < 0 || Y < 0 || X >= w_ || Y >= h_) return;
    unsigned char* p = &px_[static_cast<std::size_t>((Y * w_ + X) * 3)];
    p[0] = static_cast<unsigned char>(p[0] * (1 - alpha) + c.r * alpha);
    p[1] = static_cast<unsigned char>(p[1] * (1 - alpha) + c.g * alpha);
    p[2] = static_cast<unsigned char>(p[2] * (1 - alpha) + c.b * alpha);
  }
  // A filled disk of `radius` output pixels at canvas point p.
  void dot(const Point2& p, double radius, Rgb c) {
    const double cx = (p.x - x0_) * zoom_, cy = (p.y - y0_) * zoom_;
    for (int Y = static_cast<int>(cy - radius - 1); Y <= static_cast<int>(cy + radius + 1); ++Y)
      for (int X = static_cast<int>(cx - radius - 1); X <= static_cast<int>(cx + radius + 1); ++X) {
        const double d = std::hypot(X + 0.5 - cx, Y + 0.5 - cy);
        if (d <= radius) set(X, Y, c, std::min(1.0, radius - d + 0.5));
      }
  }
  Point2 canvas(int X, int Y) const { return {x0_ + (X + 0.5) / zoom_, y0_ + (Y + 0.5) / zoom_}; }
  int width() const { return w_; }
  int height() const { return h_; }
  bool write(const char* file) const { return stbi_write_png(file, w_, h_, 3, px_.data(), w_ * 3) != 0; }

 private:
  int w_, h_;
  double x0_, y0_, zoom_;
  std::vector<unsigned char> px_;
};

// Distance from each output pixel to the nearest gold sample, stamped locally around every sample.
std::vector<double> distance_field(const Image& img, const std::vector<Point2>& gold, double zoom, double x0, double y0,
                                   double reach) {
  std::vector<double> d(static_cast<std::size_t>(img.width() * img.height()), INFINITY);
  for (const auto& g : gold) {
    const int cx = static_cast<int>((g.x - x0) * zoom), cy = static_cast<int>((g.y - y0) * zoom);
    const int r = static_cast<int>(reach * zoom) + 2;
    for (int Y = std::max(0, cy - r); Y < std::min(img.height(), cy + r); ++Y)
      for (int X = std::max(0, cx - r); X < std::min(img.width(), cx + r); ++X) {
        const Point2 p = img.canvas(X, Y);
        auto& cell = d[static_cast<std::size_t>(Y * img.width() + X)];
        cell = std::min(cell, std::hypot(p.x - g.x, p.y - g.y));
      }
  }
  return d;
}

double credit(double d, const sc::writing::WritingScoreParams& p) {
  if (d <= p.tolerance_px) return 1.0;
  if (d >= p.cutoff_px) return 0.0;
  return (p.cutoff_px - d) / (p.cutoff_px - p.tolerance_px);
}

Rgb credit_colour(double c) {
  if (c >= 1.0) return {30, 150, 60};  // full credit: green
  if (c <= 0.0) return {215, 40, 40};  // no credit: red
  return {240, 150, 20};               // partial: orange
}

double nearest(const Point2& q, const std::vector<Point2>& set) {
  double best = INFINITY;
  for (const auto& s : set) best = std::min(best, std::hypot(s.x - q.x, s.y - q.y));
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: writing_score_figure OUT.png\n");
    return 2;
  }
  const sc::writing::WritingScoreParams params;
  const auto gold = sc::writing::gold_trajectory({"b-a-t-", sc::writing::AlphabetKind::Classic, {}}).points();

  // The learner: follows the gold, drifts up to 12 px off in the middle of the 'a', stops at 85 %.
  std::vector<TracePoint> learner;
  const std::size_t stop = gold.size() * 85 / 100;
  for (std::size_t i = 0; i < stop; i += 6) {
    const double u = static_cast<double>(i) / static_cast<double>(gold.size());
    const double drift = 12.0 * std::exp(-std::pow((u - 0.42) / 0.07, 2));
    learner.push_back({gold[i].x + 1.2 * std::sin(0.05 * static_cast<double>(i)), gold[i].y + drift, true});
  }
  const auto score = sc::writing::score_writing(gold, learner, params);
  std::printf("score %.4f recall %.4f precision %.4f f %.4f\n", score.score, score.recall, score.precision,
              score.f_measure);

  // The canvas region x in [-5, 355], y in [55, 200] (the whole word), 2.5x.
  const double zoom = 2.5, x0 = -5.0, y0 = 55.0;
  Image img(static_cast<int>(360 * zoom), static_cast<int>(145 * zoom), x0, y0, zoom);
  const auto gold_ink = sc::writing::resample_ink(gold, params.spacing_px);
  const auto learner_ink = sc::writing::resample_ink(learner, params.spacing_px);
  // Credit band: light green within the tolerance, fading out to the cutoff.
  const auto field = distance_field(img, gold_ink, zoom, x0, y0, params.cutoff_px);
  for (int Y = 0; Y < img.height(); ++Y)
    for (int X = 0; X < img.width(); ++X) {
      const double c = credit(field[static_cast<std::size_t>(Y * img.width() + X)], params);
      if (c > 0) img.set(X, Y, {200, 235, 200}, 0.35 + 0.65 * c);
    }
  // Gold ink (dark grey); gold the learner missed (recall loss) in blue.
  for (const auto& g : gold_ink) {
    const bool covered = credit(nearest(g, learner_ink), params) >= 1.0;
    img.dot(g, covered ? 1.3 : 2.2, covered ? Rgb{60, 60, 60} : Rgb{40, 90, 220});
  }
  // Learner ink samples coloured by their credit (precision).
  for (std::size_t i = 0; i < learner_ink.size(); i += 4)
    img.dot(learner_ink[i], 2.4, credit_colour(credit(nearest(learner_ink[i], gold_ink), params)));
  // The learner's raw samples (what the mouse reported) as black rings' centres.
  for (const auto& p : learner) img.dot({p.x, p.y}, 1.0, {0, 0, 0});
  if (!img.write(argv[1])) {
    std::fprintf(stderr, "writing_score_figure: cannot write %s\n", argv[1]);
    return 1;
  }
  return 0;
}
