#include "teaching/records/pending_writes.hpp"

#include "engine/core/atomic_file.hpp"
#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "teaching/records/record_json.hpp"

namespace sc::records {
namespace {

constexpr std::string_view kSpillFormat = "skillcoach-pending-writes";
constexpr int kSpillVersion = 1;

Json write_to_json(const PendingWrite& write) {
  Json out = std::visit(
      [](const auto& w) -> Json {
        using T = std::decay_t<decltype(w)>;
        if constexpr (std::is_same_v<T, TrialWrite>) return trial_to_json(w.trial, w.seq);
        if constexpr (std::is_same_v<T, DiagnosisRecord>) return diagnosis_to_json(w);
        if constexpr (std::is_same_v<T, CurriculumRecord>) return curriculum_to_json(w);
        if constexpr (std::is_same_v<T, ProgressWrite>)
          return {{"session_id", w.session_id}, {"progress", progress_to_json(w.progress)}};
        if constexpr (std::is_same_v<T, FinishWrite>) return {{"session_id", w.session_id}, {"finished", w.finished}};
      },
      write);
  out["type"] = write_type(write);
  return out;
}

PendingWrite write_from_json(const JsonView& node) {
  const auto type = node.at("type").string();
  if (type == "trial") return TrialWrite{trial_from_json(node), trial_seq_from_json(node)};
  if (type == "diagnosis") return diagnosis_from_json(node);
  if (type == "curriculum") return curriculum_from_json(node);
  if (type == "progress")
    return ProgressWrite{node.at("session_id").integer(), progress_from_json(node.at("progress"))};
  if (type == "finish") return FinishWrite{node.at("session_id").integer(), node.at("finished").string()};
  node.at("type").fail("unknown pending write type \"" + type + "\"");
}

}  // namespace

std::int64_t session_of(const PendingWrite& write) {
  return std::visit(
      [](const auto& w) -> std::int64_t {
        if constexpr (std::is_same_v<std::decay_t<decltype(w)>, TrialWrite>)
          return w.trial.session_id;
        else
          return w.session_id;
      },
      write);
}

std::string_view write_type(const PendingWrite& write) {
  static constexpr std::string_view kNames[] = {"trial", "diagnosis", "curriculum", "progress", "finish"};
  return kNames[write.index()];
}

void write_spill_file(const std::filesystem::path& spill, const std::filesystem::path& database,
                      const std::deque<PendingWrite>& writes) {
  Json doc = {{"format", kSpillFormat}, {"version", kSpillVersion}, {"database", database.string()}};
  Json list = Json::array();
  for (const auto& write : writes) list.push_back(write_to_json(write));
  doc["writes"] = std::move(list);
  // write_json_file() without fsync is not enough here: the spill exists precisely for the case where the
  // machine may go down before the database is writable again.
  write_file_atomically(spill, doc.dump(1) + "\n", FileDurability::Durable);
}

std::vector<PendingWrite> read_spill_file(const std::filesystem::path& spill) {
  const Json doc = read_json_file(spill);
  const JsonView root(doc, spill.string());
  if (root.at("format").string() != kSpillFormat) root.at("format").fail("not a SkillCoach pending-writes file");
  if (root.at("version").integer() != kSpillVersion) root.at("version").fail("unsupported version");
  const auto list = root.at("writes");
  std::vector<PendingWrite> writes;
  for (std::size_t i = 0; i < list.size(); ++i) writes.push_back(write_from_json(list.at(i)));
  return writes;
}

}  // namespace sc::records
