// A full disk for one process, without root (issue 22 item 1), loaded with LD_PRELOAD:
//   CABLEFILM_TEST_FULL_DISK=results.nc.tmp:70000,timeseries.csv.tmp:0
// names the files (those whose path holds a pattern) and the bytes each may take: a write to
// such a file beyond its budget fails with ENOSPC, as on a full disk, and from then on every
// write to any of the named files fails too (the disk is full for all). Counted are the
// low-level writes HDF5 makes (open, write, pwrite) and stdio's (fopen gives a stream whose
// writes go through the same count). Everything else passes through to the C library.
// With CABLEFILM_TEST_FULL_DISK_REPORT=FILE, the bytes written to each named file are appended
// to FILE (a line each, when it is closed): what a run writes, which may be less than the size
// of the file it leaves (HDF5 leaves the unused rows of a last chunk unwritten, a hole).
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dlfcn.h>
#include <fcntl.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

constexpr int kMaxFd = 4096;
long long g_budget[kMaxFd];   // bytes a matched file may take; -1: not matched
long long g_written[kMaxFd];  // bytes written to it so far
bool g_ready = false;
bool g_full = false;  // a named file has had its budget: the disk is full

void Ready() {
  if (g_ready) return;
  for (long long& b : g_budget) b = -1;
  g_ready = true;
}

// The budget of the first pattern `path` holds, or -1.
long long BudgetOf(const char* path) {
  const char* list = std::getenv("CABLEFILM_TEST_FULL_DISK");
  if (!path || !list) return -1;
  for (const char* p = list; *p;) {
    const char* comma = std::strchr(p, ',');
    const size_t n = comma ? static_cast<size_t>(comma - p) : std::strlen(p);
    char item[256];
    const size_t m = n < sizeof item - 1 ? n : sizeof item - 1;
    std::memcpy(item, p, m);
    item[m] = '\0';
    char* colon = std::strrchr(item, ':');
    if (colon) *colon = '\0';
    if (item[0] && std::strstr(path, item)) return colon ? std::atoll(colon + 1) : 0;
    if (!comma) break;
    p = comma + 1;
  }
  return -1;
}

void Track(int fd, const char* path) {
  Ready();
  if (fd < 0 || fd >= kMaxFd) return;
  g_budget[fd] = BudgetOf(path);
  g_written[fd] = 0;
}

// How many of `n` bytes fit: n, fewer, or -1 (none: errno ENOSPC).
ssize_t Allow(int fd, size_t n) {
  Ready();
  if (fd < 0 || fd >= kMaxFd || g_budget[fd] < 0) return static_cast<ssize_t>(n);
  const long long room = g_budget[fd] - g_written[fd];
  if (room <= 0 || g_full) {
    g_full = true;
    errno = ENOSPC;
    return -1;
  }
  if (static_cast<long long>(n) < room) return static_cast<ssize_t>(n);
  g_full = true;  // this write fills it
  return static_cast<ssize_t>(room);
}

void Wrote(int fd, ssize_t n) {
  if (n > 0 && fd >= 0 && fd < kMaxFd && g_budget[fd] >= 0) g_written[fd] += n;
}

template <typename F>
F Next(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}

mode_t ModeOf(int flags, va_list args) {
  return (flags & O_CREAT) || (flags & O_TMPFILE) == O_TMPFILE ? va_arg(args, mode_t) : 0;
}

// A stdio stream over a matched file: its writes counted against the budget.
struct Cookie {
  int fd;
};

ssize_t CookieWrite(void* c, const char* buf, size_t n) {
  return ::write(static_cast<Cookie*>(c)->fd, buf, n);  // the write below: counted there
}
ssize_t CookieRead(void* c, char* buf, size_t n) { return ::read(static_cast<Cookie*>(c)->fd, buf, n); }
int CookieSeek(void* c, off64_t* offset, int whence) {
  const off64_t at = ::lseek64(static_cast<Cookie*>(c)->fd, *offset, whence);
  if (at < 0) return -1;
  *offset = at;
  return 0;
}
int CookieClose(void* c) {
  Cookie* cookie = static_cast<Cookie*>(c);
  const int status = ::close(cookie->fd);
  delete cookie;
  return status;
}

FILE* OpenStream(const char* path, const char* mode, const char* real_name) {
  using Fopen = FILE* (*)(const char*, const char*);
  if (BudgetOf(path) < 0) return Next<Fopen>(real_name)(path, mode);
  int flags = O_WRONLY | O_CREAT | O_TRUNC;
  if (std::strchr(mode, 'a')) flags = O_WRONLY | O_CREAT | O_APPEND;
  if (std::strchr(mode, '+')) flags = (flags & ~O_WRONLY) | O_RDWR;
  if (mode[0] == 'r') flags = std::strchr(mode, '+') ? O_RDWR : O_RDONLY;
  const int fd = ::open(path, flags | O_CLOEXEC, 0666);  // tracked by open below
  if (fd < 0) return nullptr;
  cookie_io_functions_t io{CookieRead, CookieWrite, CookieSeek, CookieClose};
  FILE* f = fopencookie(new Cookie{fd}, mode, io);
  if (!f) ::close(fd);
  return f;
}

void Report(long long written) {
  const char* path = std::getenv("CABLEFILM_TEST_FULL_DISK_REPORT");
  if (!path || !*path) return;
  const int fd = Next<int (*)(const char*, int, ...)>("open")(
      path, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) return;
  char line[32];
  const int n = std::snprintf(line, sizeof line, "%lld\n", written);
  if (n > 0) Next<ssize_t (*)(int, const void*, size_t)>("write")(fd, line, static_cast<size_t>(n));
  Next<int (*)(int)>("close")(fd);
}

}  // namespace

extern "C" {

int open(const char* path, int flags, ...) {
  va_list args;
  va_start(args, flags);
  const mode_t mode = ModeOf(flags, args);
  va_end(args);
  const int fd = Next<int (*)(const char*, int, ...)>("open")(path, flags, mode);
  Track(fd, path);
  return fd;
}

int open64(const char* path, int flags, ...) {
  va_list args;
  va_start(args, flags);
  const mode_t mode = ModeOf(flags, args);
  va_end(args);
  const int fd = Next<int (*)(const char*, int, ...)>("open64")(path, flags, mode);
  Track(fd, path);
  return fd;
}

int openat(int dir, const char* path, int flags, ...) {
  va_list args;
  va_start(args, flags);
  const mode_t mode = ModeOf(flags, args);
  va_end(args);
  const int fd = Next<int (*)(int, const char*, int, ...)>("openat")(dir, path, flags, mode);
  Track(fd, path);
  return fd;
}

int creat(const char* path, mode_t mode) {
  const int fd = Next<int (*)(const char*, mode_t)>("creat")(path, mode);
  Track(fd, path);
  return fd;
}

int close(int fd) {
  Ready();
  if (fd >= 0 && fd < kMaxFd) {
    if (g_budget[fd] >= 0) Report(g_written[fd]);
    g_budget[fd] = -1;
  }
  return Next<int (*)(int)>("close")(fd);
}

ssize_t write(int fd, const void* buf, size_t n) {
  const ssize_t allowed = Allow(fd, n);
  if (allowed < 0) return -1;
  const ssize_t w =
      Next<ssize_t (*)(int, const void*, size_t)>("write")(fd, buf, static_cast<size_t>(allowed));
  Wrote(fd, w);
  return w;
}

ssize_t pwrite(int fd, const void* buf, size_t n, off_t at) {
  const ssize_t allowed = Allow(fd, n);
  if (allowed < 0) return -1;
  const ssize_t w = Next<ssize_t (*)(int, const void*, size_t, off_t)>("pwrite")(
      fd, buf, static_cast<size_t>(allowed), at);
  Wrote(fd, w);
  return w;
}

ssize_t pwrite64(int fd, const void* buf, size_t n, off64_t at) {
  const ssize_t allowed = Allow(fd, n);
  if (allowed < 0) return -1;
  const ssize_t w = Next<ssize_t (*)(int, const void*, size_t, off64_t)>("pwrite64")(
      fd, buf, static_cast<size_t>(allowed), at);
  Wrote(fd, w);
  return w;
}

ssize_t writev(int fd, const struct iovec* iov, int count) {
  size_t n = 0;
  for (int i = 0; i < count; ++i) n += iov[i].iov_len;
  if (Allow(fd, n) != static_cast<ssize_t>(n)) {
    errno = ENOSPC;
    return -1;
  }
  const ssize_t w = Next<ssize_t (*)(int, const struct iovec*, int)>("writev")(fd, iov, count);
  Wrote(fd, w);
  return w;
}

FILE* fopen(const char* path, const char* mode) { return OpenStream(path, mode, "fopen"); }
FILE* fopen64(const char* path, const char* mode) { return OpenStream(path, mode, "fopen64"); }

}  // extern "C"
