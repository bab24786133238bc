#include "teaching/records/pending_writes.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

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
  if (type == "progress") return ProgressWrite{node.at("session_id").integer(), progress_from_json(node.at("progress"))};
  if (type == "finish") return FinishWrite{node.at("session_id").integer(), node.at("finished").string()};
  node.at("type").fail("unknown pending write type \"" + type + "\"");
}

std::string errno_text() { return std::strerror(errno); }

// write_json_file() without fsync is not enough here: the spill exists precisely for the case where the
// machine may go down before the database is writable again.
void write_durably(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path tmp = temporary_sibling(file);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(file.string(), "cannot be written: " + errno_text());
  std::size_t done = 0;
  while (done < text.size()) {
    const auto n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string reason = errno_text();
      ::close(fd);
      ::unlink(tmp.c_str());
      throw InputError(file.string(), "cannot be written: " + reason);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const std::string reason = errno_text();
    ::unlink(tmp.c_str());
    throw InputError(file.string(), "cannot be written: " + reason);
  }
  if (::rename(tmp.c_str(), file.c_str()) != 0) {
    const std::string reason = errno_text();
    ::unlink(tmp.c_str());
    throw InputError(file.string(), "cannot be replaced: " + reason);
  }
  // Make the rename itself durable.
  const int dir = ::open(file.parent_path().empty() ? "." : file.parent_path().c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
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
  write_durably(spill, doc.dump(1) + "\n");
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
