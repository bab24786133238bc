#include "engine/writing/writing_trial.hpp"

#include "engine/core/error.hpp"
#include "engine/core/task_kind.hpp"

namespace sc::writing {
namespace {

TracePoint parse_point(const JsonView& p) {
  const std::size_t n = p.size();
  if (n != 2 && n != 3) p.fail("expected [x, y] or [x, y, pen], got " + std::to_string(n) + " elements");
  TracePoint point;
  point.x = p.at(std::size_t{0}).number_in(-kMaxCoordinate, kMaxCoordinate);
  point.y = p.at(std::size_t{1}).number_in(-kMaxCoordinate, kMaxCoordinate);
  if (n == 3) {
    const JsonView pen = p.at(std::size_t{2});
    if (pen.raw().is_boolean()) {
      point.pen = pen.boolean();
    } else {
      const long long v = pen.integer();
      if (v != 0 && v != 1) pen.fail("pen must be 0 (lifted) or 1 (drawing)");
      point.pen = v == 1;
    }
  }
  return point;
}

}  // namespace

WritingTrial parse_writing_trial(const Json& doc, std::string_view source) {
  const JsonView root(doc, std::string(source));
  if (!root.is_object()) root.fail("expected a JSON object (a writing trial)");
  WritingTrial trial;
  const JsonView task = root.at("task");
  if (task_kind_of(task.string()) != TaskKind::writing)
    task.fail("expected \"writing\", got \"" + task.string() + "\"");
  trial.scenario = parse_writing_scenario(root.at("scenario"));

  const JsonView points = root.at("points");
  std::size_t count = points.size();
  if (count > kMaxTrialPoints) {
    trial.warnings.push_back(std::string(source) + ": " + points.path() + ": " + std::to_string(count) +
                             " points; kept the first " + std::to_string(kMaxTrialPoints));
    count = kMaxTrialPoints;
  }
  trial.points.reserve(count);
  for (std::size_t i = 0; i < count; ++i) trial.points.push_back(parse_point(points.at(i)));

  if (auto t = root.find("t")) {
    if (t->size() != points.size())
      t->fail("has " + std::to_string(t->size()) + " time stamps for " + std::to_string(points.size()) + " points");
    trial.times.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
      const JsonView ti = t->at(i);
      const double v = ti.number();
      if (!trial.times.empty() && v < trial.times.back()) ti.fail("time goes backwards");
      trial.times.push_back(v);
    }
  }
  if (auto score = root.find("score")) trial.score = score->number_in(-1.0, 0.0);
  if (auto s = root.find("source")) trial.source = s->string();
  if (auto d = root.find("device")) trial.device = d->string();
  return trial;
}

WritingTrial read_writing_trial(const std::filesystem::path& file) {
  return parse_writing_trial(read_json_file(file), file.string());
}

Json writing_trial_json(const WritingTrial& trial) {
  bool all_pen = true;
  for (const auto& p : trial.points) all_pen = all_pen && p.pen;
  Json points = Json::array();
  for (const auto& p : trial.points) points.push_back(all_pen ? Json{p.x, p.y} : Json{p.x, p.y, p.pen ? 1 : 0});
  Json doc{{"task", "writing"}, {"scenario", writing_scenario_json(trial.scenario)}, {"points", points}};
  if (!trial.times.empty()) doc["t"] = trial.times;
  if (trial.score) doc["score"] = *trial.score;
  if (!trial.source.empty()) doc["source"] = trial.source;
  if (!trial.device.empty()) doc["device"] = trial.device;
  return doc;
}

void write_writing_trial(const std::filesystem::path& file, const WritingTrial& trial) {
  write_json_file(file, writing_trial_json(trial), -1);
}

WritingTrial gold_trial(const WritingScenario& scenario, const WordTrajectory& gold) {
  WritingTrial trial;
  trial.scenario = scenario;
  trial.points = gold.points();
  trial.times.reserve(trial.points.size());
  for (std::size_t i = 0; i < trial.points.size(); ++i)
    trial.times.push_back(static_cast<double>(i) / kExpertStepsPerSecond);
  trial.source = "expert";
  return trial;
}

WritingTrial gold_trial(const WritingScenario& scenario, const std::filesystem::path& data_dir) {
  return gold_trial(scenario, gold_trajectory(scenario, data_dir));
}

}  // namespace sc::writing
