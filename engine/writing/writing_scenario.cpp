#include "engine/writing/writing_scenario.hpp"

#include <algorithm>

namespace sc::writing {

WritingScenario parse_writing_scenario(const JsonView& node) {
  WritingScenario scenario;
  if (!node.is_object()) node.fail("expected an object like {\"word\": \"ab-c\", \"alphabet\": \"classic\"}");
  const JsonView word = node.at("word");
  scenario.word = word.string();
  if (auto alphabet = node.find("alphabet")) {
    const std::string name = alphabet->string();
    if (auto problem = alphabet_name_problem(name); !problem.empty()) alphabet->fail(problem);
    scenario.alphabet = alphabet_from_name(name, alphabet->path());
  }
  if (auto problem = word_problem(scenario.alphabet, scenario.word); !problem.empty()) word.fail(problem);
  if (auto drawers = node.find("drawers")) {
    if (!drawers->is_object()) drawers->fail("expected an object like {\"B\": 4}");
    if (scenario.alphabet == AlphabetKind::Classic)
      drawers->fail("drawer choices need \"alphabet\": \"balinese\" (classic always uses the paper's drawers)");
    for (const auto& [key, value] : drawers->raw().items()) {
      const JsonView entry = drawers->at(key);
      if (key.size() != 1 || is_connector(key[0]) || symbol_index(scenario.alphabet, key[0]) < 0)
        entry.fail("\"" + key + "\" is not a character of the balinese alphabet (A..X)");
      scenario.drawers[key[0]] = static_cast<int>(entry.integer());
      if (scenario.drawers[key[0]] < 1 || scenario.drawers[key[0]] > kDrawersPerCharacter)
        entry.fail("drawer must be in 1..15");
    }
  }
  return scenario;
}

Json writing_scenario_json(const WritingScenario& scenario) {
  Json j{{"word", scenario.word}, {"alphabet", std::string(alphabet_name(scenario.alphabet))}};
  if (!scenario.drawers.empty()) {
    Json drawers = Json::object();
    for (const auto& [symbol, drawer] : scenario.drawers) drawers[std::string(1, symbol)] = drawer;
    j["drawers"] = drawers;
  }
  return j;
}

GlyphSet load_scenario_glyphs(const WritingScenario& scenario, const std::filesystem::path& data_dir) {
  return GlyphSet::load(scenario.alphabet, data_dir, scenario.drawers);
}

WordTrajectory gold_trajectory(const WritingScenario& scenario, const std::filesystem::path& data_dir) {
  return build_word_trajectory(load_scenario_glyphs(scenario, data_dir), scenario.word);
}

double writing_time_limit_seconds(std::size_t gold_steps) {
  return std::max(kMinTimeLimitSeconds, kTimeLimitSecondsPerStep * static_cast<double>(gold_steps));
}

bool trial_ends_on_release(AlphabetKind kind) { return kind == AlphabetKind::Classic; }

}  // namespace sc::writing
