#pragma once
// The two alphabets and the glyph set a word is written with.
//  * "classic": the paper's five characters with the reference aliases a b c t e, plus the connectors - ^.
//    Goal indices a=0 b=1 c=2 t=3 e=4 -=5 ^=6 (reference order). Always the paper's drawers.
//  * "balinese": all 24 Omniglot Balinese characters, upper-case A..X = character01..character24
//    (Omniglot ids 0108..0131), plus - ^. Goal indices A=0 .. X=23, -=24, ^=25. The paper's five are
//    B (a), H (b), L (c), M (t), U (e). Each character can be written after any of its 15 drawers.
#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "engine/writing/glyph.hpp"

namespace sc::writing {

enum class AlphabetKind { Classic, Balinese };

inline constexpr int kBalineseCharacters = 24;
inline constexpr int kDrawersPerCharacter = 15;

std::string_view alphabet_name(AlphabetKind kind);  // "classic" / "balinese"
// Throws InputError(where, ...) listing the valid names.
AlphabetKind alphabet_from_name(std::string_view name, std::string_view where);
// The problem with a name ("unknown alphabet ..."), or an empty string when it names an alphabet.
std::string alphabet_name_problem(std::string_view name);

// Symbols in goal-index order.
std::string_view alphabet_symbols(AlphabetKind kind);
int symbol_index(AlphabetKind kind, char symbol);  // -1 when the symbol is not in the alphabet
bool is_connector(char symbol);

// Omniglot character number 1..24 of a (non-connector) symbol, and its default drawer 1..15: the paper's
// drawer for the five classic characters, drawer 1 for the others.
int character_number(AlphabetKind kind, char symbol);
int default_drawer(AlphabetKind kind, char symbol);
// "characterNN/CCCC_DD.txt" relative to the data folder (CCCC = 0107 + character number).
std::string stroke_file_name(int character, int drawer);

// Chosen drawers per character symbol (balinese only); missing symbols use default_drawer.
using DrawerChoice = std::map<char, int>;

// assets/omniglot-balinese (throws InputError when missing).
std::filesystem::path omniglot_data_dir();

// The glyphs of one alphabet with one drawer per character, loaded from the stroke files.
class GlyphSet {
 public:
  // Throws InputError for unreadable stroke files, drawers outside 1..15, drawer choices for symbols that
  // are not characters of the alphabet, or any drawer choice with the classic alphabet.
  static GlyphSet load(AlphabetKind kind, const std::filesystem::path& data_dir, const DrawerChoice& drawers = {});

  AlphabetKind kind() const { return kind_; }
  const DrawerChoice& drawers() const { return drawers_; }
  // Throws InputError when the symbol is not in the alphabet.
  const Glyph& glyph(char symbol) const;

 private:
  AlphabetKind kind_ = AlphabetKind::Classic;
  DrawerChoice drawers_;  // the effective drawer of every character symbol
  std::map<char, Glyph> glyphs_;
};

}  // namespace sc::writing
