// Input scripts for the trainer window (`skillcoach --script FILE.json`, app/gui/input_script.hpp):
// read from a real file; the reader must return or throw sc::InputError, and its bounds must hold: nested
// repeats are read recursively (depth bounded) and expanded (work bounded), so a deep or huge script is
// one error, never a crash, an exhausted memory or a hang.
#include "app/gui/input_script.hpp"
#include "engine/core/error.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = sc::fuzz::scratch_dir() / "script.json";
  sc::fuzz::write_bytes(file, sc::fuzz::as_text(data, size));
  try {
    const sc::InputScript script = sc::read_input_script(file);
    sc::fuzz::fuzz_require(script.steps.size() <= 200000, "expanded step limit not applied");
  } catch (const sc::InputError&) {}
  return 0;
}
