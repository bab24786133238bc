#include "engine/writing/alphabet.hpp"

#include <cstdio>

#include "engine/core/asset_paths.hpp"
#include "engine/core/error.hpp"

namespace sc::writing {
namespace {

constexpr std::string_view kClassicSymbols = "abcte-^";
constexpr std::string_view kBalineseSymbols = "ABCDEFGHIJKLMNOPQRSTUVWX-^";
// The paper's files 0109_04, 0115_03, 0119_04, 0120_02, 0128_02 as (character number, drawer).
struct ClassicSource {
  char alias;
  char balinese;
  int character;
  int drawer;
};
constexpr ClassicSource kClassicSources[] = {
    {'a', 'B', 2, 4}, {'b', 'H', 8, 3}, {'c', 'L', 12, 4}, {'t', 'M', 13, 2}, {'e', 'U', 21, 2}};

std::string quoted(char c) { return std::string("'") + c + "'"; }

}  // namespace

std::string_view alphabet_name(AlphabetKind kind) { return kind == AlphabetKind::Classic ? "classic" : "balinese"; }

std::string alphabet_name_problem(std::string_view name) {
  if (name == "classic" || name == "balinese") return {};
  return "unknown alphabet \"" + std::string(name) + "\" (expected \"classic\" or \"balinese\")";
}

AlphabetKind alphabet_from_name(std::string_view name, std::string_view where) {
  if (auto problem = alphabet_name_problem(name); !problem.empty()) throw InputError(where, problem);
  return name == "classic" ? AlphabetKind::Classic : AlphabetKind::Balinese;
}

std::string_view alphabet_symbols(AlphabetKind kind) {
  return kind == AlphabetKind::Classic ? kClassicSymbols : kBalineseSymbols;
}

int symbol_index(AlphabetKind kind, char symbol) {
  auto pos = alphabet_symbols(kind).find(symbol);
  return pos == std::string_view::npos ? -1 : static_cast<int>(pos);
}

bool is_connector(char symbol) { return symbol == '-' || symbol == '^'; }

int character_number(AlphabetKind kind, char symbol) {
  if (is_connector(symbol) || symbol_index(kind, symbol) < 0)
    throw InputError("alphabet " + std::string(alphabet_name(kind)), quoted(symbol) + " is not a character");
  if (kind == AlphabetKind::Balinese) return symbol - 'A' + 1;
  for (const auto& s : kClassicSources)
    if (s.alias == symbol) return s.character;
  throw InputError("alphabet classic", quoted(symbol) + " is not a character");
}

int default_drawer(AlphabetKind kind, char symbol) {
  const int number = character_number(kind, symbol);
  for (const auto& s : kClassicSources)
    if (s.character == number) return s.drawer;
  return 1;
}

std::string stroke_file_name(int character, int drawer) {
  char name[64];
  std::snprintf(name, sizeof name, "character%02d/%04d_%02d.txt", character, 107 + character, drawer);
  return name;
}

std::filesystem::path omniglot_data_dir() { return asset_path("omniglot-balinese"); }

GlyphSet GlyphSet::load(AlphabetKind kind, const std::filesystem::path& data_dir, const DrawerChoice& drawers) {
  const std::string where = "alphabet " + std::string(alphabet_name(kind));
  if (kind == AlphabetKind::Classic && !drawers.empty())
    throw InputError(where, "drawer choices need the \"balinese\" alphabet (classic always uses the paper's drawers)");
  for (const auto& [symbol, drawer] : drawers) {
    if (is_connector(symbol) || symbol_index(kind, symbol) < 0)
      throw InputError(where, "drawer chosen for " + quoted(symbol) + ", which is not a character of the alphabet");
    if (drawer < 1 || drawer > kDrawersPerCharacter)
      throw InputError(where, "drawer " + std::to_string(drawer) + " for " + quoted(symbol) + " is outside 1..15");
  }
  GlyphSet set;
  set.kind_ = kind;
  for (char symbol : alphabet_symbols(kind)) {
    if (is_connector(symbol)) {
      set.glyphs_.emplace(symbol, connector_glyph(symbol));
      continue;
    }
    auto chosen = drawers.find(symbol);
    const int drawer = chosen != drawers.end() ? chosen->second : default_drawer(kind, symbol);
    const std::string file = stroke_file_name(character_number(kind, symbol), drawer);
    const StrokeDrawing drawing = read_stroke_file(data_dir / file);
    set.drawers_[symbol] = drawer;
    set.glyphs_.emplace(symbol, kind == AlphabetKind::Classic ? classic_glyph(symbol, drawing, file)
                                                              : balinese_glyph(symbol, drawing, file));
  }
  return set;
}

const Glyph& GlyphSet::glyph(char symbol) const {
  auto it = glyphs_.find(symbol);
  if (it == glyphs_.end())
    throw InputError("alphabet " + std::string(alphabet_name(kind_)),
                     quoted(symbol) + " is not a symbol (valid: " + std::string(alphabet_symbols(kind_)) + ")");
  return it->second;
}

}  // namespace sc::writing
