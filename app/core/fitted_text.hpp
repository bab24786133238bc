#pragma once
// Text cut to a width in pixels, so that a long label (a learner's name, a file name) cannot push a layout
// wider than it was drawn for. `measure` gives a string's width in the caller's font (ImGui's CalcTextSize);
// cuts fall between whole UTF-8 code points, and a cut is shown as "...".
#include <functional>
#include <string>

namespace sc {

using TextMeasure = std::function<float(const std::string&)>;

// `text` if it fits, else its longest beginning that fits with "..." after it ("..." alone if none does).
std::string fitted_to_width(const std::string& text, float width, const TextMeasure& measure);

// `text` if it fits, else its beginning and end around "..." with as much of each as fits, the end favoured
// (a file name's end says which file it is).
std::string fitted_in_middle(const std::string& text, float width, const TextMeasure& measure);

}  // namespace sc
