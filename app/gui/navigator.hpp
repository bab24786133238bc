#pragma once
// Which screen is shown. Screens ask for a change with go_to()/back(); the change happens between frames
// (apply_pending) so a screen is never destroyed while its draw() is running.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/gui/screen.hpp"

namespace sc {

class Navigator {
 public:
  // Throws InputError listing the registered screens when `first_screen` is unknown.
  Navigator(AppServices& services, const std::string& first_screen);

  // Whether a screen of that name exists in this build (later work registers more).
  static bool is_available(std::string_view name) { return find_screen(name) != nullptr; }
  // Returns false (and changes nothing) for a screen that is not registered.
  bool go_to(const std::string& name);
  void back();  // to the previous screen, if any
  void request_quit() { quit_requested_ = true; }
  bool quit_requested() const { return quit_requested_; }

  // Performs a requested change; returns true if the current screen changed.
  bool apply_pending();
  Screen& current() { return *current_; }
  const std::string& current_name() const { return history_.back(); }

 private:
  void enter(const std::string& name);

  AppServices& services_;
  std::unique_ptr<Screen> current_;
  std::vector<std::string> history_;
  std::optional<std::string> pending_;
  bool pending_back_ = false;
  bool quit_requested_ = false;
};

}  // namespace sc
