// Configuration files: the gamepad section of the settings file (engine/input/gamepad_config_json.hpp)
// and CompILE configs (teaching/skills/compile_config.hpp: the "config" of model headers and sidecars).
// First byte (mod 2) chooses: 0 settings file ({"gamepad": {...}} or the bare section), 1 CompILE config.
// What is accepted must write and read back unchanged.
#include "engine/core/error.hpp"
#include "engine/input/gamepad_config_json.hpp"
#include "teaching/skills/compile_config.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

void read_gamepad(const sc::Json& doc) {
  const sc::JsonView root(doc, "settings.json");
  const auto section = root.is_object() ? root.find("gamepad") : std::nullopt;
  const auto config = sc::input::gamepad_config_from_json(section ? *section : root);
  const sc::Json written = sc::input::to_json(config);
  const auto back = sc::input::gamepad_config_from_json(sc::JsonView(written, "written"));
  sc::fuzz::fuzz_require(sc::input::to_json(back) == written, "gamepad config changed in a write/read round trip");
}

void read_compile_config(const sc::Json& doc) {
  const sc::CompileConfig config = sc::compile_config_from_json(sc::JsonView(doc, "config.json"));
  config.validate("config.json");
  const sc::Json written = sc::to_json(config);
  const sc::CompileConfig back = sc::compile_config_from_json(sc::JsonView(written, "written"));
  sc::fuzz::fuzz_require(sc::to_json(back) == written, "CompILE config changed in a write/read round trip");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  try {
    const sc::Json doc = sc::parse_json_text(sc::fuzz::as_text(data + 1, size - 1), "config.json");
    if (data[0] % 2 == 0)
      read_gamepad(doc);
    else
      read_compile_config(doc);
  } catch (const sc::InputError&) {}
  return 0;
}
