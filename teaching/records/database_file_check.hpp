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

// True when we cannot write the file or its directory and no write-ahead log holds unmerged pages:
// such a database is read through an `immutable=1` connection, which creates no -shm/-wal files (a -shm
// created now would keep the file's read-only permissions and block writing after the user fixes them).
bool read_immutably(const std::filesystem::path& file);

// `newest_version` is the newest schema this build understands.
DatabaseFileState check_database_file(const std::filesystem::path& file, int newest_version);

}  // namespace sc::records
