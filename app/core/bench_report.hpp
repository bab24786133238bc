#pragma once
// The report `skillcoach bench` writes (docs/benchmarks.md): machine info, then one table row per
// benchmark with the median and the spread of its repetitions. No Google Benchmark types here, so the
// formatting is tested without running (or timing) anything: tests/cli/bench_report_test.cpp.
#include <map>
#include <string>
#include <vector>

namespace sc::bench {

// Every repetition of one benchmark (a name such as "records/insert_trial_30kB").
struct BenchmarkSamples {
  std::string name;
  std::string label;                                    // what the benchmark says it measured (may be "")
  std::string time_unit;                                // "ns", "us", "ms" or "s"
  std::vector<double> times;                            // one per repetition, in time_unit
  long long iterations = 0;                             // iterations per repetition (the last one)
  std::map<std::string, std::vector<double>> counters;  // user counters, one value per repetition
  std::string error;                                    // non-empty when the benchmark reported an error
};

// Order statistics of a sample (linear interpolation between order statistics, like numpy's default).
struct SampleSummary {
  double median = 0, min = 0, max = 0, q1 = 0, q3 = 0;
  int count = 0;
};
// Throws std::invalid_argument for an empty sample.
SampleSummary summarize(std::vector<double> values);

struct MachineInfo {
  std::string cpu_model;  // /proc/cpuinfo "model name"
  int logical_cpus = 0;
  double memory_gib = 0;     // /proc/meminfo MemTotal
  std::string os;            // /etc/os-release PRETTY_NAME and the kernel release
  std::string compiler;      // the compiler that built this binary
  std::string build_type;    // CMake build type and sanitizers
  std::string load_average;  // /proc/loadavg before the run: the machine may be shared
};
MachineInfo probe_machine();

struct BenchReport {
  MachineInfo machine;
  std::string command;     // the exact command line that produced the report
  std::string date_utc;    // "2024-05-01 10:00 UTC"
  std::string settings;    // e.g. "5 repetitions, min time 0.5 s per repetition"
  std::string load_after;  // /proc/loadavg after the run
  std::vector<BenchmarkSamples> results;
};

// At least three significant digits, an exponent only outside [1e-3, 1e6):
// 1234.6 -> "1235", 12.345 -> "12.3", 1.2345 -> "1.23", 0.0012345 -> "0.00123", 3.2e7 -> "3.2e+07".
std::string format_significant(double value);
std::string render_markdown(const BenchReport& report);

}  // namespace sc::bench
