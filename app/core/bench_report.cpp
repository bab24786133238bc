#include "app/core/bench_report.hpp"

#include <sys/utsname.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace sc::bench {
namespace {

// The p-quantile (0 <= p <= 1) of sorted values, interpolating linearly between order statistics.
double quantile(const std::vector<double>& sorted, double p) {
  const double position = p * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (position - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

std::string printf_string(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

// The value of `key` in a "key: value" or "key=value" text file, "" when absent.
std::string field_of(const char* file, const std::string& key, char separator) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key, 0) != 0) continue;
    const auto at = line.find(separator);
    if (at == std::string::npos) continue;
    std::string value = line.substr(at + 1);
    value.erase(0, value.find_first_not_of(" \t\""));
    while (!value.empty() && (value.back() == '"' || value.back() == ' ')) value.pop_back();
    return value;
  }
  return "";
}

std::string compiler_name() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("GCC ") + __VERSION__;
#else
  return "unknown compiler";
#endif
}

std::string build_description() {
#ifdef SKILLCOACH_BUILD_TYPE
  std::string type = SKILLCOACH_BUILD_TYPE;
#else
  std::string type;
#endif
  if (type.empty()) type = "unknown build type";
#ifndef __OPTIMIZE__
  type += ", not optimised";
#endif
#ifndef NDEBUG
  type += ", assertions on";
#endif
#if defined(__SANITIZE_ADDRESS__)
  type += ", AddressSanitizer (timings are not representative)";
#endif
  return type;
}

// Markdown table cells must not contain '|' or line breaks.
std::string cell(std::string text) {
  std::string out;
  for (char c : text) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n' || c == '\r')
      out += ' ';
    else
      out += c;
  }
  return out;
}

std::string range(double lo, double hi, const std::string& unit) {
  return format_significant(lo) + " – " + format_significant(hi) + " " + unit;
}

std::string counters_cell(const BenchmarkSamples& b) {
  std::string out;
  for (const auto& [name, values] : b.counters) {
    if (values.empty()) continue;
    if (!out.empty()) out += ", ";
    out += name + " " + format_significant(summarize(values).median);
  }
  return out.empty() ? "" : cell(out);
}

std::string result_row(const BenchmarkSamples& b) {
  if (!b.error.empty() || b.times.empty()) {
    const std::string why = b.error.empty() ? "no repetitions ran" : b.error;
    return "| " + cell(b.name) + " | error: " + cell(why) + " | | | | |\n";
  }
  const SampleSummary s = summarize(b.times);
  std::ostringstream row;
  row << "| " << cell(b.label.empty() ? b.name : b.name + " (" + b.label + ")") << " | " << format_significant(s.median)
      << ' ' << b.time_unit << " | " << range(s.min, s.max, b.time_unit) << " | " << range(s.q1, s.q3, b.time_unit)
      << " | " << s.count << " × " << b.iterations << " | " << counters_cell(b) << " |\n";
  return row.str();
}

}  // namespace

SampleSummary summarize(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("summarize: empty sample");
  std::sort(values.begin(), values.end());
  SampleSummary s;
  s.count = static_cast<int>(values.size());
  s.min = values.front();
  s.max = values.back();
  s.median = quantile(values, 0.5);
  s.q1 = quantile(values, 0.25);
  s.q3 = quantile(values, 0.75);
  return s;
}

std::string format_significant(double value) {
  if (!std::isfinite(value)) return value != value ? "nan" : (value > 0 ? "inf" : "-inf");
  const double magnitude = std::fabs(value);
  if (magnitude == 0) return "0";
  if (magnitude >= 1e6 || magnitude < 1e-3) return printf_string("%.3g", value);
  if (magnitude >= 100) return printf_string("%.0f", value);
  if (magnitude >= 10) return printf_string("%.1f", value);
  if (magnitude >= 1) return printf_string("%.2f", value);
  // Three significant digits below 1: as many decimals as leading zeros after the point, plus three.
  const int decimals = 2 - static_cast<int>(std::floor(std::log10(magnitude)));
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

MachineInfo probe_machine() {
  MachineInfo m;
  m.cpu_model = field_of("/proc/cpuinfo", "model name", ':');
  if (m.cpu_model.empty()) m.cpu_model = "unknown";
  m.logical_cpus = static_cast<int>(std::thread::hardware_concurrency());
  const std::string mem_kib = field_of("/proc/meminfo", "MemTotal", ':');
  if (!mem_kib.empty()) m.memory_gib = std::strtod(mem_kib.c_str(), nullptr) / (1024.0 * 1024.0);
  m.os = field_of("/etc/os-release", "PRETTY_NAME", '=');
  utsname uts{};
  if (uname(&uts) == 0) m.os += std::string(m.os.empty() ? "" : ", ") + uts.sysname + " " + uts.release;
  m.compiler = compiler_name();
  m.build_type = build_description();
  std::ifstream load("/proc/loadavg");
  std::string one, five, fifteen;
  if (load >> one >> five >> fifteen) m.load_average = one + " " + five + " " + fifteen;
  return m;
}

std::string render_markdown(const BenchReport& r) {
  std::ostringstream md;
  md << "# Benchmarks\n\n"
     << "Generated by `skillcoach bench` on " << r.date_utc << "; do not edit by hand, re-run the command:\n\n"
     << "```\n"
     << r.command << "\n```\n\n"
     << "Settings: " << r.settings << ". Benchmarks are measurements, never timed tests.\n\n"
     << "## Machine\n\n"
     << "| | |\n|---|---|\n"
     << "| CPU | " << cell(r.machine.cpu_model) << " |\n"
     << "| Logical CPUs | " << r.machine.logical_cpus << " |\n"
     << "| Memory | " << printf_string("%.1f", r.machine.memory_gib) << " GiB |\n"
     << "| OS | " << cell(r.machine.os) << " |\n"
     << "| Compiler | " << cell(r.machine.compiler) << " |\n"
     << "| Build | " << cell(r.machine.build_type) << " |\n"
     << "| Load average (1, 5, 15 min) before / after | " << cell(r.machine.load_average) << " / " << cell(r.load_after)
     << " |\n\n"
     << "## Results\n\n"
     << "Each repetition reports the mean time per iteration (wall clock, or the benchmark's own manual time);\n"
     << "the table gives the median over repetitions, the full range and the interquartile range (Q1 – Q3).\n"
     << "Counters are benchmark-specific (rates are per second of wall time); their median is shown.\n\n"
     << "| Benchmark | Median | Min – max | IQR | Repetitions × iterations | Counters |\n"
     << "|---|---:|---:|---:|---:|---|\n";
  for (const auto& b : r.results) md << result_row(b);
  if (r.results.empty()) md << "| (no benchmark matched) | | | | | |\n";
  // Whole trainings take minutes and are one run each, so they are timed as commands, not benchmarked here.
  md << "\n## Complete model trainings\n\n"
     << "Not measured by this command: a complete training takes minutes, timed once with\n"
     << "`/usr/bin/time -v skillcoach train-skills --task parking|writing ...`. The commands and their wall times\n"
     << "and peak memory are in `docs/skills.md` (\"Parking model\", \"Writing model\").\n";
  return md.str();
}

}  // namespace sc::bench
