#include "engine/core/error.hpp"

namespace sc {

std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n' || c == '\r' || c == '\t') {
      out.push_back(' ');
    } else if (byte < 0x20 || byte == 0x7f) {
      // File names and JSON strings may hold terminal escapes (ESC[2J clears the screen): shown as text.
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out.push_back(kHex[byte >> 4]);
      out.push_back(kHex[byte & 0xf]);
    } else {
      out.push_back(c);
    }
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

InputError::InputError(std::string_view where, std::string_view problem)
    : std::runtime_error(one_line(std::string(where) + ": " + std::string(problem))) {}

InputError::InputError(std::string_view message) : std::runtime_error(one_line(message)) {}

}  // namespace sc
