#include "app/gui/screen.hpp"

#include <algorithm>

namespace sc {
namespace {
// Filled only during static initialisation, read-only afterwards (same pattern as the CLI commands).
std::vector<ScreenSpec>& registry() {
  static std::vector<ScreenSpec> screens;
  return screens;
}
}  // namespace

ScreenRegistration::ScreenRegistration(ScreenSpec spec) { registry().push_back(std::move(spec)); }

std::vector<ScreenSpec> registered_screens() {
  auto screens = registry();
  std::sort(screens.begin(), screens.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return screens;
}

const ScreenSpec* find_screen(std::string_view name) {
  for (const auto& spec : registry())
    if (spec.name == name) return &spec;
  return nullptr;
}

std::string registered_screen_names() {
  std::string names;
  for (const auto& spec : registered_screens()) names += (names.empty() ? "" : ", ") + spec.name;
  return names;
}

}  // namespace sc
