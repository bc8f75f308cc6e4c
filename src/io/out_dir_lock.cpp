#include "io/out_dir_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "scene/text_escape.h"

namespace cablefilm {

const char OutDirLock::kFileName[] = ".cablefilm.lock";

namespace {

// The holder's process id as it wrote it in the file ("" when it has not written it yet).
std::string HolderOf(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  if (n <= 0) return "";
  std::string pid(text, static_cast<size_t>(n));
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) return "";
  return pid;
}

}  // namespace

void OutDirLock::Lock(const std::string& folder, const std::string& what) {
  Release();
  const std::string path = folder + "/" + kFileName;
  // The file may be removed by its holder as it lets go (after this run opened it): the lock
  // is then on a file no longer in the folder, and is taken again on the new one.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0)
      throw Error("cannot lock the " + what + " " + EscapeText(folder) + " (" +
                  EscapeText(path) + "): " + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string holder = HolderOf(fd);
      ::close(fd);
      if (error == EWOULDBLOCK)
        throw Error("the " + what + " " + EscapeText(folder) + " is in use by another cablefilm" +
                    (holder.empty() ? std::string(" run") : " run (process " + holder + ")") +
                    ", which writes its results there; expected one run at a time in a "
                    "folder: wait for it to end or give another --out");
      throw Error("cannot lock the " + what + " " + EscapeText(folder) + " (" + EscapeText(path) +
                  "): " + std::strerror(error));
    }
    struct stat held {}, named {};
    if (::fstat(fd, &held) == 0 && ::stat(path.c_str(), &named) == 0 &&
        held.st_ino == named.st_ino && held.st_dev == named.st_dev) {
      // Without the number (a full disk, say) the lock holds all the same; another run's
      // message then names no process.
      const std::string pid = std::to_string(::getpid()) + "\n";
      const bool written =
          ::ftruncate(fd, 0) == 0 && ::pwrite(fd, pid.data(), pid.size(), 0) > 0;
      (void)written;
      fd_ = fd;
      path_ = path;
      ledger_.Open(folder);
      return;
    }
    ::close(fd);  // removed or replaced after we opened it: again
  }
  throw Error("cannot lock the " + what + " " + EscapeText(folder) + " (" + EscapeText(path) +
              "): it keeps being replaced");
}

void OutDirLock::Release() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // still held: no other run has it before it is gone
  ::close(fd_);
  fd_ = -1;
  path_.clear();
}

OutDirLock::~OutDirLock() { Release(); }

}  // namespace cablefilm
