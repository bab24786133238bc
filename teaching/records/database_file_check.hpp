#pragma once
// Decides whether an existing file may be opened as the learner database, without ever writing to it:
// the header is read with plain file I/O, then a read-only SQLite connection (which cannot write or
// checkpoint) checks the structure, the application id and the schema version. Anything wrong becomes a
// one-line sc::InputError naming the file and the problem, and the file stays byte-for-byte the same.
#include <filesystem>

namespace sc::records {

struct DatabaseFileState {
  bool is_new = false;     // missing, empty, or an empty SQLite file: the schema will be created
  int schema_version = 0;  // user_version of an existing SkillCoach database
};

// `newest_version` is the newest schema this build understands.
DatabaseFileState check_database_file(const std::filesystem::path& file, int newest_version);

}  // namespace sc::records
