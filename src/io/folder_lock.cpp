#include "io/folder_lock.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

namespace pound::io {
namespace {

// "process 1234 on host-a", from what the holder wrote into the lock file, if it has yet.
std::string holder_of(int fd) {
  std::array<char, 256> buffer{};
  const ssize_t size = ::pread(fd, buffer.data(), buffer.size() - 1, 0);
  if (size <= 0) return "another process (its PID is not known yet)";
  std::string text(buffer.data(), static_cast<std::size_t>(size));
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  const std::size_t space = text.find(' ');
  if (space == std::string::npos) return fmt::format("process {}", text);
  return fmt::format("process {} on {}", text.substr(0, space), text.substr(space + 1));
}

std::string this_process() {
  std::array<char, 256> host{};
  if (::gethostname(host.data(), host.size() - 1) != 0) host[0] = '\0';
  return fmt::format("{} {}\n", ::getpid(), host.data());
}

}  // namespace

FolderLock::FolderLock(const std::string& folder) {
  const std::string path = (std::filesystem::path(folder) / kLockFileName).string();
  // O_CLOEXEC: a program this process starts must not inherit (and outlive it holding) the lock.
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw OutputError(fmt::format("{}: cannot open the lock file: {}", path, std::strerror(errno)));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    std::string message =
        error == EWOULDBLOCK
            ? fmt::format(
                  "{}: in use by another batch ({} holds {}): wait for it to finish, or "
                  "choose another --out",
                  folder, holder_of(fd_), path)
            : fmt::format("{}: cannot lock {}: {}", folder, path, std::strerror(error));
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK) throw FolderInUse(message);
    throw OutputError(message);
  }
  // Who holds it, for the message above; a failure here costs only that message.
  const std::string holder = this_process();
  if (::ftruncate(fd_, 0) == 0) (void)!::pwrite(fd_, holder.data(), holder.size(), 0);
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the last descriptor releases the flock
}

FolderLock::FolderLock(FolderLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}

FolderLock& FolderLock::operator=(FolderLock&& other) noexcept {
  std::swap(fd_, other.fd_);
  return *this;
}

}  // namespace pound::io
