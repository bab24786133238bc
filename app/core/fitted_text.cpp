#include "app/core/fitted_text.hpp"

#include <cstddef>

namespace sc {
namespace {

bool continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// Removes the last code point of `s`.
void drop_last(std::string& s) {
  while (!s.empty() && continuation(s.back())) s.pop_back();
  if (!s.empty()) s.pop_back();
}

// Removes the first code point of `s`.
void drop_first(std::string& s) {
  std::size_t n = s.empty() ? 0 : 1;
  while (n < s.size() && continuation(s[n])) ++n;
  s.erase(0, n);
}

}  // namespace

std::string fitted_to_width(const std::string& text, float width, const TextMeasure& measure) {
  if (measure(text) <= width) return text;
  std::string cut = text;
  while (!cut.empty() && measure(cut + "...") > width) drop_last(cut);
  return cut + "...";
}

std::string fitted_in_middle(const std::string& text, float width, const TextMeasure& measure) {
  if (measure(text) <= width) return text;
  // Split at the middle code point, then shorten the head first (two head code points per tail one).
  std::size_t at = text.size() / 2;
  while (at < text.size() && continuation(text[at])) ++at;
  std::string head = text.substr(0, at), tail = text.substr(at);
  for (int turn = 0; !(head.empty() && tail.empty()) && measure(head + "..." + tail) > width; ++turn) {
    if ((turn % 3 != 2 && !head.empty()) || tail.empty())
      drop_last(head);
    else
      drop_first(tail);
  }
  return head + "..." + tail;
}

}  // namespace sc
