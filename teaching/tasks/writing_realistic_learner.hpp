#pragma once
// Realistic writing learners: classic words as a person writes them with a mouse, for measuring skill models
// and diagnoses on input that is not the expert's gold (evaluate-skills --robustness, --planted-weaknesses)
// and for augmenting skill-model training data.
//
// Why: the expert's words are chains of pixel-identical glyphs, and a model that only ever saw those
// mis-segments a learner's wobbly, resized or differently shaped letters. What a real hand adds, each a
// separate knob so a measurement can name what hurts:
//  * letters by other Omniglot drawers (the same classic pipeline on the drawer's stroke file, all strokes
//    joined into one because the classic canvas has no pen lifts). The 15 drawers are split once:
//    drawers 1..10 may be used for training, 11..15 never are (the paper's drawers, 2..4, are training ones);
//  * per-letter affine variation (scale, shear, rotation of the letter's pen steps, so letters still chain);
//  * a smooth wobble: a displacement that varies slowly along the path (three sinusoids per axis with random
//    wavelengths of 30..150 px of path), peak |offset| = wobble_px on each axis;
//  * mouse sampling: the pen moves at a speed that varies along the word, positions are read at the mouse's
//    event rate and rounded to the screen's pixel grid (screen px per canvas px random per learner); equal
//    consecutive readings are dropped, as the window system reports motion only;
//  * hesitations: pauses at letter starts (and rarely mid-letter) during which the hand trembles by a
//    screen pixel.
// Everything is drawn from sc::Rng: the same seed gives the same trace.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "engine/core/rng.hpp"
#include "engine/writing/alphabet.hpp"
#include "engine/writing/glyph.hpp"
#include "engine/writing/infill.hpp"

namespace sc {

inline constexpr int kFirstUnseenDrawer = 11;
std::vector<int> training_drawers();  // 1..10
std::vector<int> unseen_drawers();    // 11..15

// The five classic characters as drawn by each of the 15 drawers, plus the connectors.
class ClassicDrawerGlyphs {
 public:
  // Throws InputError for a missing or unreadable stroke file.
  static ClassicDrawerGlyphs load(const std::filesystem::path& data_dir = writing::omniglot_data_dir());
  // Drawer 0 = the paper's drawer (the expert's glyph); connectors ignore the drawer.
  const writing::Glyph& glyph(char symbol, int drawer) const;

 private:
  std::map<std::pair<char, int>, writing::Glyph> glyphs_;
};

// A classic word as drawn, one point per pen step (like WordTrajectory::points()), and where each symbol
// begins: step i goes from points[i] to points[i + 1].
struct WrittenWord {
  std::string word;
  std::vector<writing::TracePoint> points;
  std::vector<int> symbol_starts;  // point index of each symbol's first point (symbol_starts[0] = 0)
  // Interior boundaries as step indices (symbol_starts without the first).
  std::vector<int> interior_boundaries() const;
};

// `drawers[k]` draws the k-th symbol (0 = the paper's drawer); empty = the paper's drawer throughout.
// Throws InputError for a word that is not classic or a drawers list of another length.
WrittenWord written_word(const ClassicDrawerGlyphs& glyphs, std::string_view word,
                         const std::vector<int>& drawers = {});

// Shape noise: keeps the number of points and their indices, so boundaries (and any labels per step) carry over.
struct HandNoise {
  double wobble_px = 0.0;  // peak displacement per axis
  double affine = 0.0;     // per letter: x and y scales in 1 +- affine, shear in +-affine, rotation in +-affine/2 rad
};
WrittenWord perturbed(const WrittenWord& word, const HandNoise& noise, Rng& rng);

struct MouseSampling {
  double events_hz = 125.0;                               // mouse reports per second
  double speed_min = 150.0, speed_max = 450.0;            // mean pen speed of the learner, canvas px/s
  double screen_scale_min = 1.2, screen_scale_max = 2.4;  // screen px per canvas px
  double hesitations_per_letter = 0.3;  // chance of a pause at a letter start (a tenth of it mid-letter)
  double hesitation_seconds_max = 0.6;
};

// A sampled trace with each symbol's first point.
struct SampledTrace {
  writing::TimedTrace trace;
  std::vector<int> symbol_starts;
};
SampledTrace mouse_sampled(const WrittenWord& word, const MouseSampling& mouse, Rng& rng);
// The trace at every drawn point, time-stamped at 100 points per second (no sampling).
SampledTrace unsampled(const WrittenWord& word);

// One realistic learner's hand.
struct RealisticHand {
  HandNoise noise;
  bool mouse = true;
  MouseSampling sampling;
  std::vector<int> drawer_pool;  // each letter by a drawer drawn from here; empty = the paper's drawers
};
// The word written by `hand`, deterministic in `seed`.
SampledTrace realistic_trace(const ClassicDrawerGlyphs& glyphs, std::string_view word, const RealisticHand& hand,
                             std::uint64_t seed);

// Symbol starts as action indices of the infilled trace (what writing_step_sequence gives the skill model):
// the infill inserts midpoints between each pair of points independently, so the counts add up.
std::vector<int> infilled_symbol_starts(const writing::TimedTrace& trace, const std::vector<int>& symbol_starts);

}  // namespace sc
