#pragma once
// Shared helpers for the learner-store tests: scratch directories, file bytes, realistic records, and
// running a piece of a test in a child process (for SIGKILL and for dropping root privileges, since
// root ignores file permissions).
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "teaching/records/learner_store.hpp"

namespace sc::records::test {

// An empty directory for one test under $SKILLCOACH_TEST_OUTPUT/records/ (or a per-process directory in
// /tmp when the variable is missing, so concurrent runs from several build trees never share files).
inline std::filesystem::path fresh_dir(const std::string& name) {
  const char* root = std::getenv("SKILLCOACH_TEST_OUTPUT");
  const std::filesystem::path base =
      root != nullptr ? std::filesystem::path(root) / "records"
                      : std::filesystem::temp_directory_path() / ("skillcoach-records-" + std::to_string(getpid()));
  std::filesystem::path dir = base / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string file_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

inline void write_bytes(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << bytes;
}

inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// A parking trajectory-file document with `steps` actions (about 60 bytes per step).
inline std::string parking_trajectory(int steps, int variant) {
  Json actions = Json::array();
  Json states = Json::array();
  for (int i = 0; i < steps; ++i) {
    const double t = 0.2 * i + 0.01 * variant;
    actions.push_back({std::sin(t) * 0.8, std::cos(t) * 0.5});
    states.push_back({10.0 + t, 5.0 - 0.5 * t, 0.1 * t, 1.5});
  }
  return Json{
      {"task", "parking"},
      {"scenario",
       {{"heading0", 0.25 * variant}, {"goal", {{"x", 3.0}, {"y", -2.0}, {"heading", 1.57}}}, {"variant", "classic"}}},
      {"actions", actions},
      {"states", states},
      {"source", "learner"}}
      .dump();
}

inline NewSession sample_session(const std::string& learner = "Ada", const std::string& task = "parking") {
  return {learner, task, "adaptive", 42u, R"({"pretest_count":5})", "2024-05-01T10:00:00.000Z", ""};
}

inline TrialRecord sample_trial(std::int64_t session_id, int index, TrialKind kind = TrialKind::Pretest,
                                std::optional<double> score = std::nullopt) {
  TrialRecord t;
  t.session_id = session_id;
  t.kind = kind;
  t.round = 1;
  t.task = "parking";
  t.scenario_json = R"({"heading0":)" + std::to_string(0.25 * index) + R"(,"variant":"classic"})";
  t.trajectory_json = parking_trajectory(40, index);
  t.score = score ? score : std::optional<double>(-1.0 + 0.1 * index);
  t.device = "keyboard";
  t.started = "2024-05-01T10:0" + std::to_string(index % 10) + ":00.000Z";
  t.finished = "2024-05-01T10:0" + std::to_string(index % 10) + ":30.000Z";
  t.progress_after = SessionProgress{1, SessionPhase::Pretest, index + 1};
  return t;
}

// Runs `body` in a forked child and returns its exit code (or 128 + signal). A child that fails a
// gtest assertion exits with 1. With `as_nobody`, a root child drops to uid/gid 65534 first so file
// permissions apply to it.
inline int run_in_child(const std::function<int()>& body, bool as_nobody = false) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (as_nobody && geteuid() == 0) {
      if (setgid(65534) != 0 || setuid(65534) != 0) _exit(90);
    }
    int code = 1;
    try {
      code = body();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "child: %s\n", e.what());
      code = 91;
    }
    if (::testing::Test::HasFailure()) code = 1;
    std::fflush(nullptr);
    _exit(code);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace sc::records::test
