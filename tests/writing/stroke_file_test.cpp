#include "engine/writing/stroke_file.hpp"

#include <string>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/writing/alphabet.hpp"

namespace sc::writing {
namespace {

std::string error_of(std::string_view text) {
  try {
    parse_stroke_text(text, "x.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(StrokeFile, ParsesMultiStrokeText) {
  const auto d = parse_stroke_text("START\n1,2,0\n3.5,-4e1,10\nBREAK\n\n7,8,20\r\nBREAK\n", "x.txt");
  ASSERT_EQ(d.strokes.size(), 2u);
  ASSERT_EQ(d.strokes[0].size(), 2u);
  EXPECT_EQ(d.strokes[0][1].x, 3.5);
  EXPECT_EQ(d.strokes[0][1].y, -40.0);
  EXPECT_EQ(d.strokes[0][1].t, 10.0);
  EXPECT_EQ(d.strokes[1][0].x, 7.0);
}

TEST(StrokeFile, ReadsTheShippedFiles) {
  // 0109_04 (classic 'a'): one stroke of 306 raw points; 0108_08: nine strokes.
  const auto a = read_stroke_file(omniglot_data_dir() / "character02/0109_04.txt");
  ASSERT_EQ(a.strokes.size(), 1u);
  EXPECT_EQ(a.strokes[0].size(), 306u);
  EXPECT_EQ(read_stroke_file(omniglot_data_dir() / stroke_file_name(1, 8)).strokes.size(), 9u);
  // Every one of the 24 x 15 drawings parses.
  for (int c = 1; c <= kBalineseCharacters; ++c)
    for (int d = 1; d <= kDrawersPerCharacter; ++d)
      EXPECT_FALSE(read_stroke_file(omniglot_data_dir() / stroke_file_name(c, d)).strokes.empty());
}

TEST(StrokeFile, CorruptFilesNameFileAndLine) {
  EXPECT_EQ(error_of("START\n1,2,0\n1,abc,3\nBREAK\n"),
            "x.txt: line 3: bad number \"abc\" (expected a finite decimal)");
  EXPECT_EQ(error_of("START\n1,nan,0\nBREAK\n"), "x.txt: line 2: bad number \"nan\" (expected a finite decimal)");
  EXPECT_EQ(error_of("START\ninf,1,0\nBREAK\n"), "x.txt: line 2: bad number \"inf\" (expected a finite decimal)");
  EXPECT_EQ(error_of("1,2,3\nBREAK\n"), "x.txt: line 1: data before START");
  EXPECT_EQ(error_of(""), "x.txt: no START line (not an Omniglot stroke file?)");
  EXPECT_EQ(error_of("START\n1,2,0\nBREAK\nBREAK\n"), "x.txt: line 4: empty stroke (BREAK without any x,y,t line)");
  EXPECT_EQ(error_of("START\n1,2,0\nBREAK\n3,4,5\n"), "x.txt: line 4: truncated: the last stroke has no closing BREAK");
  EXPECT_EQ(error_of("START\n"), "x.txt: line 1: no strokes");
  EXPECT_EQ(error_of("START\n1,2\nBREAK\n"),
            "x.txt: line 2: expected \"x,y,t\" (three comma-separated numbers), got \"1,2\"");
  EXPECT_EQ(error_of("START\n1,2,3,4\nBREAK\n"),
            "x.txt: line 2: expected \"x,y,t\" (three comma-separated numbers), got \"1,2,3,4\"");
  EXPECT_EQ(error_of("START\n1,2,3\nSTART\n"), "x.txt: line 3: second START (one character per file)");
  EXPECT_EQ(error_of("START\n1.2.3,2,3\nBREAK\n"), "x.txt: line 2: bad number \"1.2.3\" (expected a finite decimal)");
}

TEST(StrokeFile, MissingFile) { EXPECT_THROW(read_stroke_file("/nonexistent/0000_00.txt"), InputError); }

}  // namespace
}  // namespace sc::writing
