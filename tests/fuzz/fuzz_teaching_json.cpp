// The teaching engine's JSON forms that are stored in the learner database and read back when a session
// resumes or is reviewed: drill plans, curricula and expertise estimates. First byte (mod 3) chooses the
// form; what is accepted must write and read back unchanged.
#include "engine/core/error.hpp"
#include "teaching/curricula/curriculum_json.hpp"
#include "teaching/drills/drill_plan_json.hpp"
#include "teaching/expertise/expertise_json.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

// Reads `doc` with `from`, writes it with `to`, reads that again: the two written forms must be equal.
template <typename From, typename To>
void round_trip(const sc::Json& doc, From from, To to, const char* what) {
  const sc::Json written = to(from(sc::JsonView(doc, "form.json")));
  const sc::Json again = to(from(sc::JsonView(written, "written")));
  sc::fuzz::fuzz_require(again == written, what);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  try {
    const sc::Json doc = sc::parse_json_text(sc::fuzz::as_text(data + 1, size - 1), "form.json");
    switch (data[0] % 3) {
      case 0:
        round_trip(doc, sc::drill_plan_from_json, sc::drill_plan_to_json, "drill plan changed in a round trip");
        break;
      case 1:
        round_trip(doc, sc::curriculum_from_json, sc::curriculum_to_json, "curriculum changed in a round trip");
        break;
      default:
        round_trip(doc, sc::expertise_from_json, sc::expertise_to_json, "expertise changed in a round trip");
        break;
    }
  } catch (const sc::InputError&) {}
  return 0;
}
