// Normal (GCC) build: feeds every file of a fuzz target's seed corpus and of its regression inputs
// (crashes the fuzzer found, minimised) to the target's LLVMFuzzerTestOneInput. A crash, an abort from
// fuzz_require or an exception other than sc::InputError fails the test; so does an empty corpus.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/fuzz/fuzz_support.hpp"

namespace {

std::vector<std::filesystem::path> inputs_in(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(dir))
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::filesystem::path fuzz_dir() { return std::filesystem::path(std::getenv("SKILLCOACH_TEST_DATA")) / "fuzz"; }

void replay(const std::vector<std::filesystem::path>& files) {
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const std::string bytes = read_bytes(file);
    EXPECT_EQ(LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
  }
}

TEST(FuzzCorpusReplay, SeedCorpusIsHandled) {
  const auto files = inputs_in(fuzz_dir() / "corpus" / SKILLCOACH_FUZZ_TARGET);
  ASSERT_FALSE(files.empty()) << "no seeds in tests/fuzz/corpus/" << SKILLCOACH_FUZZ_TARGET;
  replay(files);
}

TEST(FuzzCorpusReplay, RegressionInputsAreHandled) {
  const auto files = inputs_in(fuzz_dir() / "regressions" / SKILLCOACH_FUZZ_TARGET);
  if (files.empty()) GTEST_SKIP() << "the fuzzer has found nothing for this target";
  replay(files);
}

}  // namespace
