#pragma once
// Whole-file replacement that never leaves a half-written file under the real name: the bytes go to a
// temporary sibling first, which is then renamed over the file (atomic on POSIX). The temporary's name is
// unique to the writing process and thread, so two processes saving the same file at once (two test
// programs, two app instances) cannot write into each other's temporary; the last rename wins whole.
#include <filesystem>
#include <string_view>

namespace sc {

// "<file>.<pid>-<thread hash>.tmp", in the same directory (rename must not cross file systems).
std::filesystem::path temporary_sibling(const std::filesystem::path& file);

// Normal: the rename is atomic, but after a power cut the file may still be the old one (or, on some file
// systems, empty). Durable: the bytes and then the rename are fsync'ed before returning, for data that
// exists precisely because the machine may go down before it can be stored properly (the pending-writes
// spill file of teaching/records).
enum class FileDurability { Normal, Durable };

// Writes `bytes` to `file` through temporary_sibling(file). On failure the temporary is removed and an
// InputError names `file`: "cannot be written: <reason>", "write failed (disk full?): <reason>" or
// "cannot be replaced: <reason>".
void write_file_atomically(const std::filesystem::path& file, std::string_view bytes,
                           FileDurability durability = FileDurability::Normal);

// For files the user names as output (--out): a regular or new file is written atomically as above; an
// existing device or FIFO (/dev/stdout, /dev/full, a pipe) is written in place, because replacing its node
// by a regular file would be wrong, and its write errors are reported the same way.
void write_output_file(const std::filesystem::path& file, std::string_view bytes);

}  // namespace sc
