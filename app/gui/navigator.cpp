#include "app/gui/navigator.hpp"

#include "engine/core/error.hpp"

namespace sc {

Navigator::Navigator(AppServices& services, const std::string& first_screen) : services_(services) {
  if (!is_available(first_screen))
    throw InputError("--screen " + first_screen, "unknown screen (registered: " + registered_screen_names() + ")");
  history_.push_back(first_screen);
  enter(first_screen);
}

bool Navigator::go_to(const std::string& name) {
  if (!is_available(name)) return false;
  pending_ = name;
  pending_back_ = false;
  return true;
}

void Navigator::back() {
  if (history_.size() < 2) return;
  pending_.reset();
  pending_back_ = true;
}

bool Navigator::apply_pending() {
  if (pending_back_) {
    pending_back_ = false;
    history_.pop_back();
    enter(history_.back());
    return true;
  }
  if (!pending_) return false;
  const std::string name = *pending_;
  pending_.reset();
  history_.push_back(name);
  enter(name);
  return true;
}

void Navigator::enter(const std::string& name) {
  current_ = find_screen(name)->create(services_);
  current_->on_enter();
}

}  // namespace sc
