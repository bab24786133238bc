// skillcoach demo: the headless demo (what the app runs when there is no display).
#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "app/gui/headless_demo.hpp"

namespace sc::cli {
namespace {

CommandRunner setup_demo(CLI::App& sub) {
  auto out = std::make_shared<std::string>();
  sub.add_option("--out", *out, "PNG file to write (default: ./skillcoach-demo.png)");
  return [out] { return run_headless_demo(out->empty() ? default_demo_path() : std::filesystem::path(*out)); };
}

const CommandRegistration kDemoCommandRegistration{
    {"demo", "Render the headless demo screenshot and print its path", "skillcoach demo --out demo.png", setup_demo}};

}  // namespace
}  // namespace sc::cli
