#include "engine/parking/parking_trial.hpp"

#include <cmath>
#include <numbers>

#include "engine/core/error.hpp"
#include "engine/core/task_kind.hpp"

namespace sc {
namespace {

constexpr double kGoalMatchMetres = 0.5;
constexpr double kGoalMatchRadians = 0.01;

double angle_difference(double a, double b) { return std::fabs(std::remainder(a - b, 2.0 * std::numbers::pi)); }

// The spot whose centre is within 0.5 m of (x, y), or -1.
int spot_at(double x, double y) {
  for (int k = 0; k < parking::kSpotCount; ++k) {
    const Pose p = spot_pose(k);
    if (std::hypot(p.x - x, p.y - y) <= kGoalMatchMetres) return k;
  }
  return -1;
}

ParkingAction parse_action(const JsonView& row) {
  if (!row.is_array() || row.size() != 2) row.fail("expected an array of 2 numbers [u0, u1]");
  return {row.at(std::size_t{0}).number_in(-1.0, 1.0), row.at(std::size_t{1}).number_in(-1.0, 1.0)};
}

ParkingObservation parse_observation(const JsonView& row) {
  if (!row.is_array() || row.size() != 12) row.fail("expected an array of 12 numbers (a parking observation)");
  ParkingObservation o{};
  for (std::size_t i = 0; i < 12; ++i) o[i] = row.at(i).number();
  return o;
}

void parse_goal(const JsonView& goal, ParkingScenario& s) {
  const auto spot = goal.find("spot");
  const auto x = goal.find("x");
  const auto y = goal.find("y");
  const auto heading = goal.find("heading");
  if (!spot && !(x && y)) goal.fail("needs \"spot\" or both \"x\" and \"y\"");
  if (spot) {
    s.goal_spot = static_cast<int>(spot->integer());
    if (s.goal_spot < 0 || s.goal_spot >= parking::kSpotCount) spot->fail("spot must be in 0..29");
  }
  if (x && y) {
    const int at = spot_at(x->number(), y->number());
    if (at < 0) goal.fail("(x, y) is not the centre of a parking spot");
    if (spot && at != s.goal_spot)
      goal.fail("(x, y) is the centre of spot " + std::to_string(at) + ", not of spot " + std::to_string(s.goal_spot));
    s.goal_spot = at;
  }
  if (heading) {
    const double h = heading->number();
    const double in = spot_pose(s.goal_spot).heading;
    if (angle_difference(h, in) <= kGoalMatchRadians)
      s.reverse_in = false;
    else if (angle_difference(h, in + std::numbers::pi) <= kGoalMatchRadians)
      s.reverse_in = true;
    else
      heading->fail("goal heading must point into the spot or out of it (+-pi/2)");
  }
}

template <typename Row, typename Parse>
std::vector<Row> parse_rows(const JsonView& array, std::size_t expected, Parse parse, const char* what) {
  const std::size_t n = array.size();
  if (n != expected) array.fail("expected " + std::to_string(expected) + " " + what + ", got " + std::to_string(n));
  std::vector<Row> rows;
  rows.reserve(n);
  for (std::size_t i = 0; i < n; ++i) rows.push_back(parse(array.at(i)));
  return rows;
}

}  // namespace

int ParkingTrial::control_steps() const {
  const int per_step = control_hz == parking::kSimulationHz ? parking::kSubstepsPerAction : 1;
  return static_cast<int>(actions.size()) / per_step;
}

ParkingScenario parse_parking_scenario(const JsonView& v) {
  ParkingScenario s;
  s.heading0 = v.at("heading0").number();
  if (auto variant = v.find("variant")) {
    const std::string name = variant->string();
    if (name != "classic" && name != "parked")
      variant->fail("unknown lot variant \"" + name + "\" (expected \"classic\" or \"parked\")");
    s.variant = parse_lot_variant(name, variant->path());
  }
  if (auto seed = v.find("obstacle_seed")) {
    const long long value = seed->integer();
    if (value < 0 || value > 0xFFFFFFFFLL) seed->fail("obstacle_seed must be in 0..4294967295");
    s.obstacle_seed = static_cast<std::uint32_t>(value);
  }
  // reverse_in first: a goal heading, when present, must agree with it.
  const auto reverse = v.find("reverse_in");
  if (reverse) s.reverse_in = reverse->boolean();
  const bool declared = s.reverse_in;
  parse_goal(v.at("goal"), s);
  if (reverse && s.reverse_in != declared) v.at("goal").at("heading").fail("goal heading contradicts reverse_in");
  if (auto start = v.find("start")) {
    // Drills start mid-manoeuvre; positions beyond +-1 km or speeds beyond the model's limit are corrupt.
    VehicleState st;
    st.x = start->at("x").number_in(-1000.0, 1000.0);
    st.y = start->at("y").number_in(-1000.0, 1000.0);
    st.heading = start->at("heading").number_in(-1000.0, 1000.0);
    st.speed = start->at("speed").number_in(-parking::kMaxSpeed, parking::kMaxSpeed);
    s.start = st;
  }
  return s;
}

Json parking_scenario_to_json(const ParkingScenario& s) {
  const Pose goal = goal_pose(s);
  Json doc{{"heading0", s.heading0},
           {"goal", {{"spot", s.goal_spot}, {"x", goal.x}, {"y", goal.y}, {"heading", goal.heading}}},
           {"variant", std::string(to_string(s.variant))},
           {"obstacle_seed", s.obstacle_seed},
           {"reverse_in", s.reverse_in}};
  if (s.start)
    doc["start"] = {{"x", s.start->x}, {"y", s.start->y}, {"heading", s.start->heading}, {"speed", s.start->speed}};
  return doc;
}

ParkingTrial parse_parking_trial(const Json& doc, std::string_view source) {
  const JsonView root(doc, std::string(source));
  const auto task = root.at("task");
  if (task_kind_of(task.string()) != TaskKind::parking)
    task.fail("expected \"parking\", got \"" + task.string() + "\"");
  ParkingTrial t;
  t.scenario = parse_parking_scenario(root.at("scenario"));
  if (auto hz = root.find("control_hz")) {
    t.control_hz = static_cast<int>(hz->integer());
    if (t.control_hz != parking::kControlHz && t.control_hz != parking::kSimulationHz)
      hz->fail("control_hz must be 5 or 15");
  }
  const auto actions = root.at("actions");
  const std::size_t n = actions.size();
  if (n > parking::kMaxTrialActions)
    actions.fail("has " + std::to_string(n) + " actions, more than the limit of " +
                 std::to_string(parking::kMaxTrialActions));
  if (t.control_hz == parking::kSimulationHz && n % parking::kSubstepsPerAction != 0)
    actions.fail("with control_hz 15 the number of actions must be a multiple of 3, got " + std::to_string(n));
  t.actions = parse_rows<ParkingAction>(actions, n, parse_action, "actions");
  const auto steps = static_cast<std::size_t>(t.control_steps());
  if (auto states = root.find("states"))
    t.states = parse_rows<ParkingObservation>(*states, steps + 1, parse_observation,
                                              "states (one per control step plus the start)");
  if (auto rewards = root.find("rewards"))
    t.rewards = parse_rows<double>(
        *rewards, steps, [](const JsonView& r) { return r.number(); }, "rewards (one per control step)");
  if (auto success = root.find("success")) t.success = success->boolean();
  if (auto s = root.find("source")) t.source = s->string();
  if (auto s = root.find("created")) t.created = s->string();
  if (auto s = root.find("device")) t.device = s->string();
  return t;
}

ParkingTrial read_parking_trial(const std::filesystem::path& file) {
  return parse_parking_trial(read_json_file(file), file.string());
}

Json parking_trial_to_json(const ParkingTrial& t) {
  Json doc{{"task", "parking"}, {"scenario", parking_scenario_to_json(t.scenario)}};
  if (t.control_hz != parking::kControlHz) doc["control_hz"] = t.control_hz;
  Json actions = Json::array();
  for (const auto& a : t.actions) actions.push_back({a[0], a[1]});
  doc["actions"] = std::move(actions);
  if (!t.states.empty()) doc["states"] = t.states;
  if (!t.rewards.empty()) doc["rewards"] = t.rewards;
  if (t.success) doc["success"] = *t.success;
  if (!t.source.empty()) doc["source"] = t.source;
  if (!t.created.empty()) doc["created"] = t.created;
  if (!t.device.empty()) doc["device"] = t.device;
  return doc;
}

void write_parking_trial(const std::filesystem::path& file, const ParkingTrial& trial) {
  write_json_file(file, parking_trial_to_json(trial), -1);  // compact: trials are written by the thousand
}

}  // namespace sc
