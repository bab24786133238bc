#include "engine/core/json_file.hpp"

#include <cmath>
#include <system_error>

#include "engine/core/atomic_file.hpp"
#include "engine/core/error.hpp"
#include "engine/core/input_file.hpp"

namespace sc {

Json parse_json_text(std::string_view text, std::string_view source) {
  try {
    return Json::parse(text.begin(), text.end());
  } catch (const Json::exception& e) {
    // nlohmann's message looks like "[json.exception.parse_error.101] parse error at line 3, column 5: ...".
    // Also catches out_of_range.406 ("number overflow parsing '1e999'"), which parse() throws for numbers
    // beyond double range.
    std::string what = e.what();
    auto pos = what.find("] ");
    throw InputError(source, "not valid JSON: " + (pos == std::string::npos ? what : what.substr(pos + 2)));
  }
}

Json read_json_file(const std::filesystem::path& file) {
  return parse_json_text(read_input_file(file, kMaxJsonFileBytes), file.string());
}

void write_json_file(const std::filesystem::path& file, const Json& doc, int indent) {
  // Strings that did not come from JSON (SQLite text of a damaged database, device names) may hold
  // invalid UTF-8; the default dump() then throws and the whole document (an export, a spill file of
  // pending trials) would be lost. Such bytes become U+FFFD instead (found by tests/fuzz).
  write_output_file(file, doc.dump(indent, ' ', false, Json::error_handler_t::replace) + '\n');
}

JsonView::JsonView(const Json& node, std::string source, std::string path)
    : node_(&node), source_(std::move(source)), path_(std::move(path)) {}

void JsonView::fail(std::string_view problem) const { throw InputError(source_ + ": " + path_, problem); }

namespace {
std::string type_name(const Json& j) { return j.type_name(); }
}  // namespace

JsonView JsonView::at(std::string_view key) const {
  auto member = find(key);
  if (!member) fail("missing required field \"" + std::string(key) + "\"");
  return *member;
}

std::optional<JsonView> JsonView::find(std::string_view key) const {
  if (!node_->is_object()) fail("expected an object, got " + type_name(*node_));
  auto it = node_->find(std::string(key));
  if (it == node_->end() || it->is_null()) return std::nullopt;
  return JsonView(*it, source_, path_ + "." + std::string(key));
}

JsonView JsonView::at(std::size_t index) const {
  if (!node_->is_array()) fail("expected an array, got " + type_name(*node_));
  if (index >= node_->size())
    fail("array has " + std::to_string(node_->size()) + " elements, needed index " + std::to_string(index));
  return JsonView((*node_)[index], source_, path_ + "[" + std::to_string(index) + "]");
}

std::size_t JsonView::size() const {
  if (!node_->is_array()) fail("expected an array, got " + type_name(*node_));
  return node_->size();
}

double JsonView::number() const {
  if (!node_->is_number()) fail("expected a number, got " + type_name(*node_));
  double v = node_->get<double>();
  if (!std::isfinite(v)) fail("expected a finite number");
  return v;
}

double JsonView::number_in(double lo, double hi) const {
  double v = number();
  if (v < lo || v > hi) {
    std::ostringstream msg;
    msg << "value " << v << " is outside [" << lo << ", " << hi << "]";
    fail(msg.str());
  }
  return v;
}

long long JsonView::integer() const {
  if (!node_->is_number_integer()) {
    if (node_->is_number_float()) {
      double v = node_->get<double>();
      if (std::isfinite(v) && std::floor(v) == v && std::fabs(v) < 9.0e15) return static_cast<long long>(v);
    }
    fail("expected an integer, got " + type_name(*node_));
  }
  return node_->get<long long>();
}

std::string JsonView::string() const {
  if (!node_->is_string()) fail("expected a string, got " + type_name(*node_));
  return node_->get<std::string>();
}

bool JsonView::boolean() const {
  if (!node_->is_boolean()) fail("expected true or false, got " + type_name(*node_));
  return node_->get<bool>();
}

}  // namespace sc
