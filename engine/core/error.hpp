#pragma once
// One error type for every piece of bad input (files, models, databases, configs, devices).
// Its message is always a single line that names the thing and the problem, e.g.
//   "trial.json: $.actions[3]: expected an array of 2 numbers"
// so the CLI can print it as-is and exit 2, and the app can show it in a dialog.
#include <stdexcept>
#include <string>
#include <string_view>

namespace sc {

class InputError : public std::runtime_error {
 public:
  // `where` names the file/device/option, `problem` says what is wrong with it.
  InputError(std::string_view where, std::string_view problem);
  explicit InputError(std::string_view message);
};

// Collapses newlines and tabs so a message always prints on one line.
std::string one_line(std::string_view text);

}  // namespace sc
