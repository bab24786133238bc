#include "teaching/records/record_types.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <ctime>

#include "engine/core/error.hpp"

namespace sc::records {
namespace {
constexpr std::array<std::string_view, 4> kKindNames{"pretest", "demo", "practice", "eval"};
constexpr std::array<std::string_view, 5> kPhaseNames{"pretest", "diagnosis", "drills", "evaluation", "summary"};

template <typename Names>
std::string joined(const Names& names) {
  std::string out;
  for (auto name : names) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}
}  // namespace

std::string_view to_string(TrialKind kind) { return kKindNames[static_cast<std::size_t>(kind)]; }
std::string_view to_string(SessionPhase phase) { return kPhaseNames[static_cast<std::size_t>(phase)]; }

TrialKind trial_kind_from_string(std::string_view name, std::string_view source) {
  for (std::size_t i = 0; i < kKindNames.size(); ++i)
    if (kKindNames[i] == name) return static_cast<TrialKind>(i);
  throw InputError(source, "unknown trial kind \"" + std::string(name) + "\" (expected " + joined(kKindNames) + ")");
}

SessionPhase session_phase_from_string(std::string_view name, std::string_view source) {
  for (std::size_t i = 0; i < kPhaseNames.size(); ++i)
    if (kPhaseNames[i] == name) return static_cast<SessionPhase>(i);
  throw InputError(source,
                   "unknown session phase \"" + std::string(name) + "\" (expected " + joined(kPhaseNames) + ")");
}

std::string utc_timestamp_now() {
  const auto now = std::chrono::system_clock::now();
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[80];  // generous: the compiler cannot bound tm_year
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", utc.tm_year + 1900, utc.tm_mon + 1,
                utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, static_cast<int>(ms));
  return text;
}

}  // namespace sc::records
