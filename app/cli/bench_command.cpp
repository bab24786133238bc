// skillcoach bench: runs every Google Benchmark compiled into the program (app/bench/*_bench.cpp) in this
// process and writes docs/benchmarks.md (bench_report.hpp): machine info, and per benchmark the median
// and spread over repetitions. --quick trades precision for time (fewer repetitions, shorter runs).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "app/cli/command_registry.hpp"
#include "app/core/bench_report.hpp"
#include "engine/core/error.hpp"

namespace sc::cli {
namespace {

struct BenchOptions {
  bool quick = false;
  std::string out = std::string(SKILLCOACH_SOURCE_DIR) + "/docs/benchmarks.md";
  std::string filter;
  bool out_given = false;
};

// Prints like the library's console reporter and keeps every repetition (not the aggregates the library
// computes from them: the report computes its own median and spread).
class CollectingReporter : public benchmark::ConsoleReporter {
 public:
  // No colour escapes when the output is a pipe or a CI log.
  CollectingReporter() : benchmark::ConsoleReporter(isatty(STDOUT_FILENO) ? OO_Defaults : OO_Tabular) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    benchmark::ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Iteration) continue;
      bench::BenchmarkSamples& b = samples_for(run.benchmark_name());
      b.time_unit = benchmark::GetTimeUnitString(run.time_unit);
      if (run.error_occurred) {
        b.error = run.error_message;
        continue;
      }
      b.label = run.report_label;
      b.times.push_back(run.GetAdjustedRealTime());
      b.iterations = static_cast<long long>(run.iterations);
      for (const auto& [name, counter] : run.counters) b.counters[name].push_back(counter.value);
    }
  }
  std::vector<bench::BenchmarkSamples> take() { return std::move(results_); }

 private:
  bench::BenchmarkSamples& samples_for(const std::string& name) {
    for (auto& b : results_)
      if (b.name == name) return b;
    results_.push_back({});
    results_.back().name = name;
    return results_.back();
  }
  std::vector<bench::BenchmarkSamples> results_;
};

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &tm);
  return text;
}

std::string command_line(const BenchOptions& o) {
  std::string command = "skillcoach bench";
  if (o.quick) command += " --quick";
  if (!o.filter.empty()) command += " --filter '" + o.filter + "'";
  if (o.out_given) command += " --out " + o.out;
  return command;
}

int run_bench(const BenchOptions& o) {
  const int repetitions = o.quick ? 3 : 5;
  const double min_time = o.quick ? 0.05 : 0.5;
  bench::BenchReport report;
  report.machine = bench::probe_machine();
  report.command = command_line(o);
  report.settings = std::to_string(repetitions) + " repetitions, at least " + bench::format_significant(min_time) +
                    " s per repetition unless a benchmark fixes its iteration count";

  // Google Benchmark takes its settings as command-line flags.
  std::vector<std::string> args = {"skillcoach bench", "--benchmark_repetitions=" + std::to_string(repetitions),
                                   "--benchmark_min_time=" + bench::format_significant(min_time)};
  if (!o.filter.empty()) args.push_back("--benchmark_filter=" + o.filter);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());

  CollectingReporter reporter;
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  if (ran == 0) throw InputError("--filter " + o.filter, "matches no benchmark");

  report.results = reporter.take();
  report.date_utc = utc_now();
  report.load_after = bench::probe_machine().load_average;
  const std::filesystem::path out(o.out);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  std::ofstream file(out, std::ios::trunc);
  file << bench::render_markdown(report);
  file.flush();
  if (!file) throw InputError(o.out, "cannot be written");
  std::printf("wrote %s (%zu benchmarks)\n", o.out.c_str(), report.results.size());
  return 0;
}

CommandRunner setup_bench(CLI::App& sub) {
  auto options = std::make_shared<BenchOptions>();
  sub.add_flag("--quick", options->quick, "3 short repetitions per benchmark instead of 5 of at least 0.5 s");
  auto* out = sub.add_option("--out", options->out,
                             "Markdown report to write (default: docs/benchmarks.md of the "
                             "source tree this program was built from)");
  sub.add_option("--filter", options->filter, "Only benchmarks whose name matches this regular expression");
  return [options, out] {
    options->out_given = out->count() > 0;
    // docs/benchmarks.md is the committed record of full runs; quick or partial figures would silently replace it.
    if (options->quick && !options->out_given)
      throw InputError("--quick", "its figures are too rough for docs/benchmarks.md; name a file with --out");
    if (!options->filter.empty() && !options->out_given)
      throw InputError("--filter",
                       "a partial run would replace the full record in docs/benchmarks.md; name a file "
                       "with --out");
    return run_bench(*options);
  };
}

const CommandRegistration kBenchCommandRegistration{
    {"bench", "Run every benchmark and write docs/benchmarks.md (median and spread)",
     "skillcoach bench --quick --out docs/benchmarks.md", setup_bench}};

}  // namespace
}  // namespace sc::cli
