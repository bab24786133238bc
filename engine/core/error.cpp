#include "engine/core/error.hpp"

namespace sc {

std::string one_line(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) out.push_back(c == '\n' || c == '\r' || c == '\t' ? ' ' : c);
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

InputError::InputError(std::string_view where, std::string_view problem)
    : std::runtime_error(one_line(std::string(where) + ": " + std::string(problem))) {}

InputError::InputError(std::string_view message) : std::runtime_error(one_line(message)) {}

}  // namespace sc
