#pragma once
// One writer per result name: a run holds an exclusive lock on "<name>.lock" beside its output from
// before its first write until its last, so a second `peristep` writing the same name fails at once
// with a clear message instead of truncating the first one's partial files. The lock is the kernel's
// (flock): it goes with the process, so a killed run leaves nothing that blocks the next one.
#include <filesystem>

namespace peristep::host {

// Throws InputError when the directory `file` is to be written in does not exist.
void requireOutputDirectory(const std::filesystem::path& file);

class OutputLock {
 public:
  // Throws InputError when another process writes `file` or its directory does not exist.
  explicit OutputLock(const std::filesystem::path& file);
  ~OutputLock();  // removes the lock file and releases the lock
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace peristep::host
