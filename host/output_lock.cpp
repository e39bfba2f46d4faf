#include "output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "host_errors.hpp"

namespace peristep::host {

void requireOutputDirectory(const std::filesystem::path& file) {
  if (file.has_parent_path() && !std::filesystem::is_directory(file.parent_path()))
    throw InputError(file.string() + ": the output directory " + file.parent_path().string() + " does not exist");
}

OutputLock::OutputLock(const std::filesystem::path& file) : path_(file.string() + ".lock") {
  requireOutputDirectory(file);
  // A holder removes the lock file while it still holds the lock: a lock taken on a file that has
  // since been removed (or replaced) is on the wrong inode, so take it again on the current one.
  for (;;) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw RunError(path_.string() + ": cannot create the output lock: " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd_);
      fd_ = -1;
      if (error == EWOULDBLOCK)
        throw InputError(file.string() + ": another peristep process is writing this output (lock " + path_.string() +
                         "); wait for it to finish or choose another output name");
      throw RunError(path_.string() + ": cannot lock: " + std::strerror(error));
    }
    struct stat held {}, current {};
    if (::fstat(fd_, &held) == 0 && ::stat(path_.c_str(), &current) == 0 && held.st_ino == current.st_ino &&
        held.st_dev == current.st_dev)
      return;
    ::close(fd_);
  }
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace peristep::host
