#include "teaching/expertise/expertise_json.hpp"

#include <string>

namespace sc {
namespace {

std::vector<int> skill_list(const JsonView& view, int num_skills) {
  std::vector<int> out;
  for (std::size_t i = 0; i < view.size(); ++i) {
    const long long m = view.at(i).integer();
    if (m < 0 || m >= num_skills)
      view.at(i).fail("skill id " + std::to_string(m) + " is outside [0, " + std::to_string(num_skills) + ")");
    out.push_back(static_cast<int>(m));
  }
  return out;
}

}  // namespace

Json expertise_to_json(const ExpertiseEstimate& estimate) {
  Json contributions = Json::array();
  for (const auto& per_skill : estimate.contributions) {
    Json list = Json::array();
    for (const auto& c : per_skill) {
      list.push_back({{"trial", c.trial},
                      {"scenario", c.scenario},
                      {"position", c.position},
                      {"reward", c.reward},
                      {"delta", c.delta},
                      {"execution", c.execution},
                      {"repeated", c.repeated}});
    }
    contributions.push_back(std::move(list));
  }
  Json out = {{"expertise", estimate.expertise},
              {"occurrences", estimate.occurrences},
              {"ranking", estimate.ranking},
              {"targets", estimate.targets},
              {"contributions", std::move(contributions)}};
  if (!estimate.learner_hand.empty()) out["learner_hand"] = estimate.learner_hand;
  return out;
}

ExpertiseEstimate expertise_from_json(const JsonView& view) {
  ExpertiseEstimate out;
  const JsonView e = view.at("expertise");
  const JsonView occ = view.at("occurrences");
  const JsonView contributions = view.at("contributions");
  const std::size_t n = e.size();
  if (occ.size() != n) occ.fail("has " + std::to_string(occ.size()) + " entries, expertise has " + std::to_string(n));
  if (contributions.size() != n)
    contributions.fail("has " + std::to_string(contributions.size()) + " entries, expertise has " + std::to_string(n));
  for (std::size_t m = 0; m < n; ++m) {
    const double value = e.at(m).number();
    if (value > 0.0) e.at(m).fail("expertise must be <= 0");
    out.expertise.push_back(value);
    const long long count = occ.at(m).integer();
    if (count < 0) occ.at(m).fail("occurrences must be >= 0");
    out.occurrences.push_back(static_cast<int>(count));
    std::vector<ExpertiseContribution> list;
    const JsonView per_skill = contributions.at(m);
    for (std::size_t i = 0; i < per_skill.size(); ++i) {
      const JsonView c = per_skill.at(i);
      const long long position = c.at("position").integer();
      if (position < 1) c.at("position").fail("positions count from 1");
      const auto execution = c.find("execution");  // absent in records written before quality-aware expertise
      const auto repeated = c.find("repeated");    // ... and before repeated evidence (2026-12-05)
      list.push_back({static_cast<int>(c.at("trial").integer()), static_cast<int>(c.at("scenario").integer()),
                      static_cast<int>(position), c.at("reward").number(), c.at("delta").number(),
                      execution && execution->boolean(), repeated && repeated->boolean()});
    }
    out.contributions.push_back(std::move(list));
  }
  out.ranking = skill_list(view.at("ranking"), static_cast<int>(n));
  out.targets = skill_list(view.at("targets"), static_cast<int>(n));
  if (const auto hand = view.find("learner_hand")) out.learner_hand = hand->string();
  return out;
}

}  // namespace sc
