#include "tests/support/run_skillcoach.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace sc::test {

std::string skillcoach_binary() {
  const char* binary = std::getenv("SKILLCOACH_BINARY");
  if (binary == nullptr || *binary == '\0') throw std::runtime_error("SKILLCOACH_BINARY is not set");
  return binary;
}

CommandResult run_skillcoach(std::string_view arguments, std::string_view env_prefix) {
  std::string command(env_prefix);
  if (!command.empty()) command += ' ';
  if (const char* program_env = std::getenv("SKILLCOACH_PROGRAM_ENV"); program_env != nullptr && *program_env != '\0') {
    command += program_env;
    command += ' ';
  }
  command += '\'';
  command += skillcoach_binary();
  command += "' ";
  command += arguments;
  command += " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
  return result;
}

}  // namespace sc::test
