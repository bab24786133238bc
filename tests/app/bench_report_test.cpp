// The markdown writer of `skillcoach bench`: statistics, number formatting and the report layout, with
// made-up samples (nothing is run or timed here).
#include "app/core/bench_report.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace {

using sc::bench::BenchmarkSamples;
using sc::bench::BenchReport;
using ::testing::HasSubstr;

TEST(BenchSummary, MedianQuartilesAndRangeOfAnOddSample) {
  const auto s = sc::bench::summarize({5.0, 1.0, 3.0, 2.0, 4.0});
  EXPECT_EQ(s.count, 5);
  EXPECT_DOUBLE_EQ(s.median, 3.0);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 5.0);
  EXPECT_DOUBLE_EQ(s.q1, 2.0);
  EXPECT_DOUBLE_EQ(s.q3, 4.0);
}

TEST(BenchSummary, EvenSampleInterpolatesLikeNumpy) {
  // numpy.percentile([1, 2, 4, 10], [25, 50, 75]) = [1.75, 3.0, 5.5]
  const auto s = sc::bench::summarize({10.0, 1.0, 4.0, 2.0});
  EXPECT_DOUBLE_EQ(s.median, 3.0);
  EXPECT_DOUBLE_EQ(s.q1, 1.75);
  EXPECT_DOUBLE_EQ(s.q3, 5.5);
}

TEST(BenchSummary, SingleValueAndEmptySample) {
  const auto s = sc::bench::summarize({7.5});
  EXPECT_DOUBLE_EQ(s.median, 7.5);
  EXPECT_DOUBLE_EQ(s.q1, 7.5);
  EXPECT_DOUBLE_EQ(s.q3, 7.5);
  EXPECT_THROW(sc::bench::summarize({}), std::invalid_argument);
}

TEST(BenchFormat, ThreeSignificantDigitsWithoutExponentInTheUsualRange) {
  EXPECT_EQ(sc::bench::format_significant(1234.6), "1235");
  EXPECT_EQ(sc::bench::format_significant(123.44), "123");
  EXPECT_EQ(sc::bench::format_significant(12.345), "12.3");
  EXPECT_EQ(sc::bench::format_significant(1.2345), "1.23");
  EXPECT_EQ(sc::bench::format_significant(0.5), "0.500");
  EXPECT_EQ(sc::bench::format_significant(0.0012345), "0.00123");
  EXPECT_EQ(sc::bench::format_significant(-2.5), "-2.50");
  EXPECT_EQ(sc::bench::format_significant(0.0), "0");
}

TEST(BenchFormat, ExponentForVeryLargeAndSmallValuesAndNamesForNonFinite) {
  EXPECT_EQ(sc::bench::format_significant(3.2e7), "3.2e+07");
  EXPECT_EQ(sc::bench::format_significant(4.56e-5), "4.56e-05");
  EXPECT_EQ(sc::bench::format_significant(std::nan("")), "nan");
  EXPECT_EQ(sc::bench::format_significant(INFINITY), "inf");
}

BenchReport example_report() {
  BenchReport r;
  r.machine.cpu_model = "Example CPU @ 2.00GHz";
  r.machine.logical_cpus = 2;
  r.machine.memory_gib = 23.4;
  r.machine.os = "Debian GNU/Linux 12 (bookworm), Linux 6.1.0";
  r.machine.compiler = "GCC 12.2.0";
  r.machine.build_type = "Release";
  r.machine.load_average = "0.50 0.40 0.30";
  r.load_after = "1.00 0.60 0.35";
  r.command = "skillcoach bench --quick";
  r.date_utc = "2024-05-01 10:00 UTC";
  r.settings = "3 repetitions";
  BenchmarkSamples insert;
  insert.name = "records/insert_trial_30kB";
  insert.time_unit = "ms";
  insert.times = {4.0, 5.25, 3.5, 4.5, 9.0};
  insert.iterations = 170;
  insert.counters["trajectory_bytes"] = {30512, 30512, 30512, 30512, 30512};
  r.results.push_back(insert);
  BenchmarkSamples frame;
  frame.name = "render/screen_frame_1280x720";
  frame.label = "start screen, osmesa";
  frame.time_unit = "ms";
  frame.times = {12.0, 11.0, 13.0};
  frame.iterations = 50;
  r.results.push_back(frame);
  BenchmarkSamples broken;
  broken.name = "render/a|b";
  broken.time_unit = "ms";
  broken.error = "no GL\ncontext";
  r.results.push_back(broken);
  return r;
}

TEST(BenchMarkdown, MachineInfoSettingsAndCommandArePresent) {
  const std::string md = sc::bench::render_markdown(example_report());
  EXPECT_THAT(md, HasSubstr("| CPU | Example CPU @ 2.00GHz |"));
  EXPECT_THAT(md, HasSubstr("| Logical CPUs | 2 |"));
  EXPECT_THAT(md, HasSubstr("| Memory | 23.4 GiB |"));
  EXPECT_THAT(md, HasSubstr("| OS | Debian GNU/Linux 12 (bookworm), Linux 6.1.0 |"));
  EXPECT_THAT(md, HasSubstr("| Compiler | GCC 12.2.0 |"));
  EXPECT_THAT(md, HasSubstr("| Build | Release |"));
  EXPECT_THAT(md, HasSubstr("0.50 0.40 0.30 / 1.00 0.60 0.35"));
  EXPECT_THAT(md, HasSubstr("```\nskillcoach bench --quick\n```"));
  EXPECT_THAT(md, HasSubstr("2024-05-01 10:00 UTC"));
  EXPECT_THAT(md, HasSubstr("Settings: 3 repetitions."));
  EXPECT_THAT(md, HasSubstr("## Complete model trainings"));  // points to docs/skills.md for whole trainings
}

TEST(BenchMarkdown, OneRowPerBenchmarkWithMedianRangeAndIqr) {
  const std::string md = sc::bench::render_markdown(example_report());
  // times 3.5 4 4.5 5.25 9: median 4.5, Q1 4, Q3 5.25.
  EXPECT_THAT(md, HasSubstr("| records/insert_trial_30kB | 4.50 ms | 3.50 – 9.00 ms | 4.00 – 5.25 ms | 5 × 170 | "
                            "trajectory_bytes 30512 |\n"));
  EXPECT_THAT(md, HasSubstr("| render/screen_frame_1280x720 (start screen, osmesa) | 12.0 ms | 11.0 – 13.0 ms | "
                            "11.5 – 12.5 ms | 3 × 50 |  |\n"));
}

TEST(BenchMarkdown, ErrorsAreShownAndCellsCannotBreakTheTable) {
  const std::string md = sc::bench::render_markdown(example_report());
  EXPECT_THAT(md, HasSubstr("| render/a\\|b | error: no GL context | | | | |\n"));
}

TEST(BenchMarkdown, EmptyResultsSayNothingMatched) {
  BenchReport r = example_report();
  r.results.clear();
  EXPECT_THAT(sc::bench::render_markdown(r), HasSubstr("(no benchmark matched)"));
}

TEST(BenchMachine, ProbeFindsThisMachine) {
  const auto m = sc::bench::probe_machine();
  EXPECT_GE(m.logical_cpus, 1);
  EXPECT_GT(m.memory_gib, 0.0);
  EXPECT_FALSE(m.cpu_model.empty());
  EXPECT_THAT(m.os, HasSubstr("Linux"));
  EXPECT_FALSE(m.compiler.empty());
  EXPECT_EQ(std::count(m.load_average.begin(), m.load_average.end(), ' '), 2);
}

}  // namespace
