#pragma once
// The SQL that writes learner records. Each function runs inside the caller's transaction, so the store
// decides what is atomic (a trial and its resume point go together). Pending writes are idempotent: a
// replayed trial with an existing (session, seq) is ignored when it is the same trial (a different one
// fails: two trainers wrote to one session), a diagnosis or curriculum of an existing
// (session, round) is replaced with the same content.
#include <cstdint>
#include <string_view>

#include "teaching/records/pending_writes.hpp"
#include "teaching/records/pg_handle.hpp"
#include "teaching/records/sqlite_handle.hpp"

namespace sc::records {

template <typename Db>
std::int64_t insert_learner_if_new(Db& db, std::string_view name, std::string_view created);
template <typename Db>
std::int64_t insert_session(Db& db, std::int64_t learner_id, const NewSession& session);
template <typename Db>
void apply_write(Db& db, const PendingWrite& write);

}  // namespace sc::records
