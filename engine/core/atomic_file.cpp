#include "engine/core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <functional>
#include <string>
#include <system_error>
#include <thread>

#include "engine/core/error.hpp"

namespace sc {

std::filesystem::path temporary_sibling(const std::filesystem::path& file) {
  const std::size_t thread = std::hash<std::thread::id>{}(std::this_thread::get_id());
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "." + std::string.
  std::string suffix(1, '.');
  suffix += std::to_string(::getpid());
  suffix += '-';
  suffix += std::to_string(thread % 1000000);
  suffix += ".tmp";
  auto tmp = file;
  tmp += suffix;
  return tmp;
}

namespace {

std::string errno_text() { return std::strerror(errno); }

// Writes all of `bytes` to `fd`, retrying after signals; false with errno set on failure.
bool write_all(int fd, std::string_view bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const auto n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& file, std::string_view bytes, FileDurability durability) {
  const bool durable = durability == FileDurability::Durable;
  const std::filesystem::path tmp = temporary_sibling(file);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(file.string(), "cannot be written: " + errno_text());
  // Every failure removes the temporary and names the file; `reason` is read before close() can change errno.
  auto fail = [&tmp, &file](const std::string& what, const std::string& reason) {
    ::unlink(tmp.c_str());
    throw InputError(file.string(), what + reason);
  };
  std::string reason;
  if (!write_all(fd, bytes) || (durable && ::fsync(fd) != 0)) reason = errno_text();
  // close() can report a deferred write error (NFS, quota), so it is checked like the writes; it runs in
  // every case, so the descriptor is never leaked.
  if (::close(fd) != 0 && reason.empty()) reason = errno_text();
  if (!reason.empty()) fail("write failed (disk full?): ", reason);
  if (::rename(tmp.c_str(), file.c_str()) != 0) fail("cannot be replaced: ", errno_text());
  if (!durable) return;
  // Make the rename itself durable.
  const int dir =
      ::open(file.parent_path().empty() ? "." : file.parent_path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

void write_output_file(const std::filesystem::path& file, std::string_view bytes) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status) || std::filesystem::is_regular_file(status) ||
      std::filesystem::is_directory(status)) {
    write_file_atomically(file, bytes);
    return;
  }
  const int fd = ::open(file.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) throw InputError(file.string(), "cannot be written: " + errno_text());
  std::string reason;
  if (!write_all(fd, bytes)) reason = errno_text();
  if (::close(fd) != 0 && reason.empty()) reason = errno_text();
  if (!reason.empty()) throw InputError(file.string(), "write failed: " + reason);
}

}  // namespace sc
