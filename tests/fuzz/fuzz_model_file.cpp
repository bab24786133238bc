// CompILE model files (teaching/skills/model_file.hpp) and the config they carry, plus the JSON sidecar.
// First byte of the input (mod 3) chooses what the rest is:
//   0  a model file as it is (exercises the magic/version/checksum checks);
//   1  a model file body to which the harness appends the correct FNV-1a checksum, so the fuzzer gets
//      past the checksum into the header, tensor table and config (a random body never matches it);
//   2  a sidecar ("<model>.json"): its "config" is read like the header's.
// What loads must give a config that validate() accepts or rejects with InputError, and tensors whose
// value count equals the product of their shape.
#include <cstring>
#include <string>

#include "engine/core/error.hpp"
#include "teaching/skills/compile_config.hpp"
#include "teaching/skills/model_file.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

void read_config(const sc::Json& doc, const std::string& name) {
  if (!doc.is_object() || !doc.contains("config")) return;
  const sc::CompileConfig config = sc::compile_config_from_json(sc::JsonView(doc, name).at("config"));
  config.validate(name + ": $.config");
  // A valid config must survive its own JSON form.
  const sc::Json again = sc::to_json(config);
  const sc::CompileConfig back = sc::compile_config_from_json(sc::JsonView(again, "again"));
  sc::fuzz::fuzz_require(sc::to_json(back) == again, "config changed in a write/read round trip");
}

void read_model(std::string bytes) {
  const auto file = sc::fuzz::scratch_dir() / "model.scm";
  sc::fuzz::write_bytes(file, bytes);
  const sc::ModelFileContents contents = sc::read_model_file(file);
  for (const auto& t : contents.tensors) {
    std::size_t elements = 1;
    for (auto d : t.shape) elements *= static_cast<std::size_t>(d);
    sc::fuzz::fuzz_require(t.values.size() == elements, "tensor value count differs from its shape");
  }
  read_config(contents.header, file.string());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const int mode = data[0] % 3;
  std::string rest(sc::fuzz::as_text(data + 1, size - 1));
  try {
    if (mode == 0) {
      read_model(rest);
    } else if (mode == 1) {
      const std::uint64_t sum = fnv1a(rest);
      char bytes[sizeof sum];
      std::memcpy(bytes, &sum, sizeof sum);
      read_model(rest + std::string(bytes, sizeof bytes));
    } else {
      read_config(sc::parse_json_text(rest, "model.scm.json"), "model.scm.json");
    }
  } catch (const sc::InputError&) {}
  return 0;
}
