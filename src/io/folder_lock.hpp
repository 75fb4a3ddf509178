#pragma once
// An exclusive lock on an output folder, so that only one process writes into it at a time. It is
// a flock(2) on <folder>/.lock: the kernel releases it when the holder exits or is killed, so a
// lock left by a dead process never blocks (a PID file would). The holder writes its PID and host
// into the file, only to name it to whoever finds the folder locked. The file itself stays: to
// remove it on release would let two processes lock two different files of the same name.
#include <string>

#include "io/output.hpp"

namespace pound::io {

// The name of the lock file inside a locked folder.
inline constexpr char kLockFileName[] = ".lock";

// Another process holds the lock (an OutputError: the folder cannot be written now).
class FolderInUse : public OutputError {
 public:
  using OutputError::OutputError;
};

class FolderLock {
 public:
  // Locks `folder` (which must exist) without waiting. Throws FolderInUse naming the folder and,
  // when it is known, the holder's PID and host; OutputError if the lock file cannot be opened
  // or the file system refuses locks.
  explicit FolderLock(const std::string& folder);
  ~FolderLock();
  FolderLock(FolderLock&& other) noexcept;
  FolderLock& operator=(FolderLock&& other) noexcept;
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace pound::io
