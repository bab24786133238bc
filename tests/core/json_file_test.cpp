#include "engine/core/json_file.hpp"

#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(JsonView, ReportsFileAndPathOfAWrongType) {
  Json doc = Json::parse(R"({"actions": [[0.5, "x"]]})");
  JsonView root(doc, "run.json");
  EXPECT_EQ(message_of([&] { root.at("actions").at(0).at(1).number(); }),
            "run.json: $.actions[0][1]: expected a number, got string");
}

TEST(JsonView, ReportsMissingFieldAndRange) {
  Json doc = Json::parse(R"({"a": 3})");
  JsonView root(doc, "f.json");
  EXPECT_EQ(message_of([&] { root.at("b"); }), "f.json: $: missing required field \"b\"");
  EXPECT_EQ(message_of([&] { root.at("a").number_in(0, 1); }), "f.json: $.a: value 3 is outside [0, 1]");
  EXPECT_EQ(root.at("a").integer(), 3);
  EXPECT_FALSE(root.find("b").has_value());
}

TEST(JsonFile, ParseErrorNamesFileAndPosition) {
  std::string msg = message_of([] { parse_json_text("{\"a\": ", "broken.json"); });
  EXPECT_EQ(msg.rfind("broken.json: not valid JSON: parse error at line 1", 0), 0u) << msg;
}

TEST(JsonFile, MissingFileIsNamed) {
  EXPECT_EQ(message_of([] { read_json_file("/nonexistent/x.json"); }), "/nonexistent/x.json: no such file");
}

TEST(JsonFile, WriteThenReadRoundTrips) {
  const char* out = std::getenv("SKILLCOACH_TEST_OUTPUT");
  std::filesystem::path file = std::filesystem::path(out ? out : "/tmp") / "json_roundtrip.json";
  Json doc = {{"x", 1.25}, {"list", {1, 2, 3}}};
  write_json_file(file, doc);
  EXPECT_EQ(read_json_file(file), doc);
  EXPECT_EQ(test::temporaries_left_of(file), 0);
}

}  // namespace
}  // namespace sc
