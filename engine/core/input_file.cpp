#include "engine/core/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "engine/core/error.hpp"

namespace sc {
namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

std::string open_problem(int error) {
  if (error == ENOENT || error == ENOTDIR) return "no such file";
  if (error == EACCES || error == EPERM) return "cannot be read: permission denied";
  return std::string("cannot be read: ") + std::strerror(error);
}

// Closes the descriptor on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_input_file(const std::filesystem::path& file, std::uintmax_t max_bytes) {
  const std::string where = file.string();
  // O_NONBLOCK: opening a FIFO without a writer returns at once instead of waiting for one; fstat on the
  // descriptor (not a stat of the name before opening) decides on the very file we would read.
  const Descriptor d{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (d.fd < 0) {
    const int error = errno;
    struct stat st {};
    if (error == EACCES && ::stat(file.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
      throw InputError(where, "is a directory");
    throw InputError(where, open_problem(error));
  }
  struct stat st {};
  if (::fstat(d.fd, &st) != 0) throw InputError(where, open_problem(errno));
  if (!S_ISREG(st.st_mode)) throw InputError(where, kind_of(st.st_mode));
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size > max_bytes)
    throw InputError(where,
                     "too large (" + std::to_string(size) + " bytes; at most " + std::to_string(max_bytes) + ")");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(d.fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(where, std::string("read error: ") + std::strerror(errno));
    if (n == 0) break;  // the file shrank while we read it: parse what is there
    done += static_cast<std::size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

}  // namespace sc
