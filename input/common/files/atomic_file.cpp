#include "files/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <string>
#include <system_error>

namespace weft {
namespace {

[[noreturn]] void fail(const std::string& step, const std::filesystem::path& file) {
  throw std::system_error(errno, std::generic_category(), step + " " + file.string());
}

void fsync_directory(const std::filesystem::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) fail("cannot open directory", dir);
  const int rc = ::fsync(fd);
  const int saved = errno;
  ::close(fd);
  errno = saved;
  if (rc != 0) fail("cannot fsync directory", dir);
}


std::filesystem::path directory_of(const std::filesystem::path& target) {
  return target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
}

// Beside the target; the pid keeps two writers (two processes) from sharing a temporary.
std::filesystem::path temporary_for(const std::filesystem::path& target) {
  return directory_of(target) / ("." + target.filename().string() + ".tmp." + std::to_string(::getpid()));
}

// The temporary's data on disk, then renamed over the target, then the rename on disk.
void replace_with(const std::filesystem::path& target, const std::filesystem::path& temp, int fd) {
  if (::fsync(fd) != 0) {
    const int saved = errno;
    ::close(fd);
    ::unlink(temp.c_str());
    errno = saved;
    fail("cannot fsync", temp);
  }
  if (::close(fd) != 0) {
    const int saved = errno;
    ::unlink(temp.c_str());
    errno = saved;
    fail("cannot close", temp);
  }
  if (::rename(temp.c_str(), target.c_str()) != 0) {
    const int saved = errno;
    ::unlink(temp.c_str());
    errno = saved;
    fail("cannot rename over " + target.string() + ": from", temp);
  }
  fsync_directory(directory_of(target));
}

}  // namespace

void write_file_atomically(const std::filesystem::path& target, std::span<const std::byte> bytes) {
  const std::filesystem::path temp = temporary_for(target);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("cannot create", temp);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int saved = errno;
      ::close(fd);
      ::unlink(temp.c_str());
      errno = saved;
      fail("cannot write", temp);
    }
    done += std::size_t(n);
  }
  replace_with(target, temp, fd);
}

void write_file_atomically(const std::filesystem::path& target,
                           const std::function<void(const std::filesystem::path& temporary)>& write) {
  const std::filesystem::path temp = temporary_for(target);
  try {
    write(temp);
  } catch (...) {
    ::unlink(temp.c_str());
    throw;
  }
  const int fd = ::open(temp.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int saved = errno;
    ::unlink(temp.c_str());
    errno = saved;
    fail("cannot open", temp);
  }
  replace_with(target, temp, fd);
}

void write_file_atomically(const std::filesystem::path& target, std::string_view text) {
  write_file_atomically(target, std::as_bytes(std::span<const char>(text.data(), text.size())));
}

}  // namespace weft
