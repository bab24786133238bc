#include "teaching/skills/model_file.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "engine/core/error.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

std::filesystem::path scratch(const std::string& name) { return test::scratch_path("model_file_test", name); }

ModelFileContents sample() {
  ModelFileContents c;
  c.header = Json{{"format", "test"}, {"n", 3}};
  c.tensors.push_back({"w", {2, 3}, {1, 2, 3, 4, 5, 6}});
  c.tensors.push_back({"b", {3}, {-1, 0.5f, 7}});
  return c;
}

// The error must be one line naming the file and containing `problem`.
void expect_error(const std::filesystem::path& p, const std::string& problem) {
  try {
    read_model_file(p);
    FAIL() << "no error for " << p;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(p.string()), std::string::npos) << what;
    EXPECT_NE(what.find(problem), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
}

TEST(ModelFile, RoundTripsExactly) {
  const auto p = scratch("ok.scm");
  write_model_file(p, sample());
  const ModelFileContents back = read_model_file(p);
  EXPECT_EQ(back.header, sample().header);
  ASSERT_EQ(back.tensors.size(), 2u);
  EXPECT_EQ(back.tensors[0].shape, (std::vector<std::int64_t>{2, 3}));
  EXPECT_EQ(back.tensors[1].values, sample().tensors[1].values);
  write_model_file(scratch("again.scm"), sample());
  EXPECT_EQ(test::read_bytes(p), test::read_bytes(scratch("again.scm")));  // deterministic bytes
}

TEST(ModelFile, RejectsBrokenFilesWithOneLineErrors) {
  const auto good = scratch("good.scm");
  write_model_file(good, sample());
  const std::string b = test::read_bytes(good);

  expect_error(scratch("does_not_exist.scm"), "no such model file");

  const auto truncated = scratch("truncated.scm");
  test::write_bytes(truncated, b.substr(0, b.size() / 2));
  expect_error(truncated, "checksum");

  const auto tiny = scratch("tiny.scm");
  test::write_bytes(tiny, b.substr(0, 12));
  expect_error(tiny, "truncated");

  std::string flipped = b;
  flipped[b.size() - 20] = static_cast<char>(flipped[b.size() - 20] ^ 0x40);
  const auto corrupt = scratch("corrupt.scm");
  test::write_bytes(corrupt, flipped);
  expect_error(corrupt, "corrupt");

  std::string newer = b;
  newer[8] = 99;  // format version field
  const auto future = scratch("future.scm");
  test::write_bytes(future, newer);
  expect_error(future, "newer than this program supports");

  const auto foreign = scratch("foreign.scm");
  test::write_bytes(foreign, "{\"this\": \"is json\"}");
  expect_error(foreign, "not a SkillCoach model file");
}

}  // namespace
}  // namespace sc
