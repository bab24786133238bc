#include "teaching/tasks/parking_expert_pool.hpp"

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/parking/parking_expert.hpp"

namespace sc {
namespace {
constexpr const char* kFormat = "skillcoach-parking-expert-pool";
constexpr int kVersion = 1;
}  // namespace

ParkingScenario parking_pool_scenario(std::uint64_t seed, int index, GoalRegion region) {
  // One forked stream per index: scenario i does not depend on how many scenarios are drawn.
  Rng rng = Rng(seed).fork(static_cast<std::uint64_t>(index));
  return sample_parking_scenario(rng, LotVariant::Classic, 0.0, region);
}

std::vector<ParkingTrial> generate_parking_pool(const ParkingPoolOptions& options) {
  if (options.count < 1) throw InputError("parking expert pool", "count must be at least 1");
  const ParkingExpert expert;
  std::vector<ParkingTrial> trials;
  trials.reserve(static_cast<std::size_t>(options.count));
  for (int i = 0; i < options.count; ++i) {
    const ParkingScenario scenario = parking_pool_scenario(options.seed, i, options.region);
    trials.push_back(expert.plan(scenario).to_trial(scenario));
  }
  return trials;
}

Json parking_pool_json(const ParkingPoolOptions& options, const std::vector<ParkingTrial>& trials) {
  Json doc = {{"format", kFormat},
              {"version", kVersion},
              {"seed", options.seed},
              {"count", trials.size()},
              {"region", std::string(to_string(options.region))}};
  Json list = Json::array();
  for (const auto& t : trials) list.push_back(parking_trial_to_json(t));
  doc["trials"] = std::move(list);
  return doc;
}

std::vector<ParkingTrial> parse_parking_pool(const Json& doc, const std::string& source,
                                             const ParkingPoolOptions& expected) {
  const JsonView root(doc, source);
  if (root.at("format").string() != kFormat) root.at("format").fail(std::string("expected \"") + kFormat + "\"");
  if (root.at("version").integer() != kVersion) root.at("version").fail("unsupported version");
  if (static_cast<std::uint64_t>(root.at("seed").integer()) != expected.seed)
    root.at("seed").fail("pool was generated with another seed (" + std::to_string(expected.seed) + " expected)");
  GoalRegion region = GoalRegion::WholeLot;
  if (const auto v = root.find("region")) region = parse_goal_region(v->string(), source + ": " + v->path());
  if (region != expected.region)
    root.fail("pool of the " + std::string(to_string(region)) + ", " + std::string(to_string(expected.region)) +
              " expected");
  const JsonView list = root.at("trials");
  if (static_cast<long long>(list.size()) != expected.count)
    list.fail("expected " + std::to_string(expected.count) + " trials, got " + std::to_string(list.size()));
  std::vector<ParkingTrial> trials;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const JsonView item = list.at(i);
    ParkingTrial t = parse_parking_trial(item.raw(), source + ": " + item.path());
    if (t.states.size() != t.actions.size() + 1 || t.rewards.size() != t.actions.size())
      item.fail("expert trials need T+1 states and T rewards");
    if (!(t.scenario == parking_pool_scenario(expected.seed, static_cast<int>(i), expected.region)))
      item.at("scenario").fail("not the scenario the seed gives for this index");
    trials.push_back(std::move(t));
  }
  return trials;
}

LoadedParkingPool load_or_generate_parking_pool(const std::filesystem::path& file, const ParkingPoolOptions& options) {
  LoadedParkingPool out;
  std::string why;
  if (std::filesystem::exists(file)) {
    try {
      out.trials = parse_parking_pool(read_json_file(file), file.string(), options);
      return out;
    } catch (const InputError& e) {
      why = e.what();
    }
  } else {
    why = file.string() + ": missing";
  }
  out.trials = generate_parking_pool(options);
  try {
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    write_json_file(file, parking_pool_json(options, out.trials));
    out.notice = why + "; regenerated and saved";
  } catch (const std::exception& e) {
    out.notice = why + "; regenerated in memory (" + one_line(e.what()) + ")";
  }
  return out;
}

}  // namespace sc
