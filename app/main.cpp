// skillcoach: with no arguments it opens the trainer window; with a subcommand it runs headless.
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include <csignal>

#include <CLI/CLI.hpp>

#include "app/cli/command_registry.hpp"
#include "app/gui/gui_main.hpp"
#include "engine/core/error.hpp"

int main(int argc, char** argv) {
  // Past a file-size limit (ulimit -f) the kernel would kill the program with SIGXFSZ in the middle of a
  // write, losing the trial being stored; ignored, the write fails with EFBIG like a full disk, and the
  // learner store keeps the trial pending and says so.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{
      "SkillCoach - learn to park a car and to write Balinese characters with individualized drills.\n"
      "Run without arguments to open the trainer; use a subcommand for headless work."};
  app.require_subcommand(0, 1);
  app.footer(
      "Examples:\n  skillcoach                       open the trainer window\n"
      "  skillcoach <command> --help      options and an example for one command");
  sc::GuiOptions gui;
  app.add_option("--data-dir", gui.data_dir, "Where learner records are kept (default: XDG data directory)");
  app.add_option("--store", gui.store,
                 "Keep the records on a class's PostgreSQL server instead (postgresql:// URL, docs/database.md); "
                 "--data-dir then holds only what the server could not take yet");
  app.add_option("--script", gui.script,
                 "Play an input script (JSON) instead of reading devices, offscreen without a display "
                 "(end-to-end tests; docs/input-script.md)")
      ->group("Testing");

  sc::cli::CommandRunner runner;
  for (auto& spec : sc::cli::registered_commands()) {
    CLI::App* sub = app.add_subcommand(spec.name, spec.description);
    if (!spec.example.empty()) sub->footer("Example:\n  " + spec.example);
    auto run = spec.setup(*sub);
    sub->callback([&runner, run] { runner = run; });
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "skillcoach: error: %s (see skillcoach --help)\n", sc::one_line(e.what()).c_str());
    return 2;
  }

  try {
    if (runner) return runner();
    return sc::run_gui(gui);
  } catch (const sc::InputError& e) {
    std::fprintf(stderr, "skillcoach: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "skillcoach: error: %s\n", sc::one_line(e.what()).c_str());
    return 1;
  }
}
