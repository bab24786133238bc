#pragma once
// Reading and writing JSON documents with one-line errors that name the file and the JSON path:
//   "run.json: $.actions[3][1]: expected a finite number, got string"
// JsonView walks a parsed document and remembers where it is, so every parser in SkillCoach reports
// problems the same way.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace sc {

using Json = nlohmann::json;

// Parses a file; throws InputError("<file>: <problem>") when it is missing, unreadable or not JSON.
Json read_json_file(const std::filesystem::path& file);
// Parses text that came from `source` (a file name or description used in errors).
Json parse_json_text(std::string_view text, std::string_view source);
// Writes atomically (temporary file + rename) so a crash never leaves half a document; an existing device
// or FIFO (/dev/stdout) is written in place (write_output_file).
void write_json_file(const std::filesystem::path& file, const Json& doc, int indent = 1);

class JsonView {
 public:
  JsonView(const Json& node, std::string source, std::string path = "$");

  JsonView at(std::string_view key) const;                   // required member of an object
  std::optional<JsonView> find(std::string_view key) const;  // optional member (null counts as absent)
  JsonView at(std::size_t index) const;                      // element of an array
  std::size_t size() const;                                  // requires an array
  bool is_array() const { return node_->is_array(); }
  bool is_object() const { return node_->is_object(); }

  double number() const;                         // finite number
  double number_in(double lo, double hi) const;  // finite and within [lo, hi]
  long long integer() const;
  std::string string() const;
  bool boolean() const;

  const Json& raw() const { return *node_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(std::string_view problem) const;

 private:
  const Json* node_;
  std::string source_;
  std::string path_;
};

}  // namespace sc
