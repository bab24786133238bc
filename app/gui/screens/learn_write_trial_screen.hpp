#pragma once
// The trainer's trial screen for the writing task (the "learn_trial" screen shows it when the task is
// writing): pre-test and evaluation words traced over the goal word, and drills — first the ghost pen writes
// the drill, then the learner traces it over the drill's ribbon.
#include <memory>

#include "app/gui/screen.hpp"

namespace sc {

std::unique_ptr<Screen> make_learn_write_trial_screen(AppServices& services);

}  // namespace sc
