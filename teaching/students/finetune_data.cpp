#include "teaching/students/finetune_data.hpp"

#include <string>

#include "engine/core/error.hpp"
#include "teaching/students/bc_datasets.hpp"

namespace sc {
namespace {

CurriculumConfig finetune_config(const FinetuneMaterial& material, int budget) {
  CurriculumConfig config = CurriculumConfig::parking();
  config.drills.num_targets = material.num_targets;
  config.budget_steps = budget;
  return config;
}

CurriculumInputs inputs_of(const FinetuneMaterial& material, std::uint64_t seed) {
  return CurriculumInputs{material.expert_skills, {}, material.diagnosis, seed};
}

int total_steps(const std::vector<PracticeItem>& items) {
  int total = 0;
  for (const PracticeItem& item : items) total += item.total_steps();
  return total;
}

// The condition's curriculum with at least `min_steps` steps and `min_items` items. make_curriculum draws
// its items from one seeded stream in order, so a larger budget only appends items: doubling it keeps the
// prefix.
std::vector<PracticeItem> material_items(StudyCondition condition, const FinetuneMaterial& material, int min_steps,
                                         std::size_t min_items, std::uint64_t seed) {
  for (int budget = std::max(min_steps, 16);; budget *= 2) {
    std::vector<PracticeItem> items =
        make_curriculum(condition, inputs_of(material, seed), finetune_config(material, budget)).items;
    if ((total_steps(items) >= min_steps && items.size() >= min_items) || budget > (1 << 24)) return items;
  }
}

}  // namespace

int individualized_round_pairs(const FinetuneMaterial& material, std::uint64_t seed) {
  if (material.diagnosis.ranking.empty()) throw InputError("fine-tuning data", "the diagnosis ranks no skill");
  const DrillBuilder builder(material.expert_skills, finetune_config(material, 1).drills);
  Rng unused(0);  // the round's size in drills does not depend on the segments drawn
  const std::size_t drills = builder.individualized(material.diagnosis, unused).size();
  const std::vector<PracticeItem> items = material_items(StudyCondition::IndDrills, material, 1, drills, seed);
  int pairs = 0;
  for (std::size_t i = 0; i < drills && i < items.size(); ++i) pairs += items[i].total_steps();
  return pairs;
}

FinetuneData finetune_data(StudyCondition condition, const FinetuneMaterial& material, int pairs, std::uint64_t seed) {
  if (condition != StudyCondition::IndDrills && condition != StudyCondition::Drills &&
      condition != StudyCondition::FullTrajectory)
    throw InputError("fine-tuning data", std::string(condition_name(condition)) + " is not a fine-tuning condition");
  if (pairs < 1) throw InputError("fine-tuning data", "the data size must be >= 1 pair, got " + std::to_string(pairs));
  FinetuneData out;
  out.condition = condition;
  for (PracticeItem& item : material_items(condition, material, pairs, 1, seed)) {
    if (out.pairs.size() >= pairs) break;
    const BcDataset one = bc_dataset_from_plan(item.material, material.expert_steps);
    for (int k = 0; k < item.sessions && out.pairs.size() < pairs; ++k) out.pairs.append(one);
    out.items.push_back(std::move(item));
  }
  out.pairs = first_pairs(out.pairs, pairs);
  return out;
}

}  // namespace sc
