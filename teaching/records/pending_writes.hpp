#pragma once
// Records that could not be written to the database yet (disk full, read-only, locked). The store keeps
// them in order in memory and, as a last resort, in a JSON "spill" file next to the database, written
// atomically (temporary file, fsync, rename) so a finished trial survives even if the database never
// becomes writable again. The next store opened on that database replays the spill file.
#include <cstdint>
#include <deque>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "teaching/records/record_types.hpp"

namespace sc::records {

struct TrialWrite {
  TrialRecord trial;
  int seq = 0;
};
struct ProgressWrite {
  std::int64_t session_id = 0;
  SessionProgress progress;
};
struct FinishWrite {
  std::int64_t session_id = 0;
  std::string finished;
};

using PendingWrite = std::variant<TrialWrite, DiagnosisRecord, CurriculumRecord, ProgressWrite, FinishWrite>;

std::int64_t session_of(const PendingWrite& write);
// "trial", "diagnosis", ... for messages and the spill file.
std::string_view write_type(const PendingWrite& write);

// Throws sc::InputError naming the spill file when it cannot be written (nothing is replaced then).
void write_spill_file(const std::filesystem::path& spill, const std::filesystem::path& database,
                      const std::deque<PendingWrite>& writes);
// Throws sc::InputError naming the file and JSON path when it is unreadable or malformed.
std::vector<PendingWrite> read_spill_file(const std::filesystem::path& spill);

}  // namespace sc::records
