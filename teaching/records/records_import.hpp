#pragma once
// `skillcoach import`: writes the records of a `skillcoach export` document (records_export.hpp) into a
// store, so records move between a desktop's SQLite file and a shared PostgreSQL database without loss:
// learners, studies with every participant's place and condition, sessions with their settings, resume
// point and end, every trial in order, diagnoses and curricula. Stored ids are the destination's own (the
// export of the destination equals the source's but for "id" and "session_id").
// A learner the store already holds keeps their sessions and gains the document's other ones: a desktop that
// trained offline brings its sessions to the class store, each a session of its own. A session the store
// already has (same learner, task and start time) is skipped, so importing the same document twice adds nothing.
#include <cstddef>
#include <string>

#include "engine/core/json_file.hpp"
#include "teaching/records/record_store.hpp"

namespace sc::records {

struct RecordsImport {
  std::size_t learners = 0;
  std::size_t sessions = 0;                // added
  std::size_t sessions_already_there = 0;  // skipped: the store had them
  std::size_t trials = 0;
  std::size_t studies = 0;
};

// Throws sc::InputError naming `source` for a document of another format or version, or naming the store
// when it already holds one of the document's studies (a study is created whole), when a record is refused
// or cannot be stored now, or when the store would give a participant another condition than the export
// records (the study's seed and order decide it).
RecordsImport import_records(const Json& doc, const std::string& source, RecordStore& store);

}  // namespace sc::records
