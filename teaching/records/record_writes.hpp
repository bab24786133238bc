#pragma once
// The SQL that writes learner records. Each function runs inside the caller's transaction, so the store
// decides what is atomic (a trial and its resume point go together). Pending writes are idempotent: a
// replayed trial with an existing (session, seq) is ignored when it is the same trial (a different one
// fails: two trainers wrote to one session), a diagnosis or curriculum of an existing
// (session, round) is replaced with the same content.
#include <cstdint>
#include <string_view>

#include "teaching/records/pending_writes.hpp"
#include "teaching/records/sqlite_handle.hpp"

namespace sc::records {

std::int64_t insert_learner_if_new(SqliteDb& db, std::string_view name, std::string_view created);
std::int64_t insert_session(SqliteDb& db, std::int64_t learner_id, const NewSession& session);
void apply_write(SqliteDb& db, const PendingWrite& write);

}  // namespace sc::records
