// The libc calls a program's camera code makes, wrapped (the shim is
// preloaded, so these definitions come before libc's): a call on one of the
// robot's camera paths or camera fds goes to the emulated device
// (V4l2Device.hpp), every other call to libc's own function unchanged.
// Covered: open, open64, openat, openat64 (and the _FORTIFY_SOURCE entry
// points __open_2, ...), close, ioctl, mmap, mmap64, read, fstat, fstat64,
// fstatat, fstatat64, stat, stat64, lstat, lstat64 (NaoTH stats the path
// before it opens it) and the older __fxstat, __xstat, __lxstat and their
// 64 forms (binaries built against glibc before 2.33). Not covered (docs/porting.md section 3): dup
// of a camera fd (the copy is a plain FIFO), statx, a raw syscall.
#include <fcntl.h>
#include <stdarg.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "shim/Export.hpp"
#include "shim/Real.hpp"
#include "shim/V4l2Device.hpp"

namespace v4 = simswift::shim::v4l2;
using simswift::shim::real;

namespace {

// The mode argument, present when the flags create a file.
mode_t modeOf(int flags, va_list ap) {
  return (flags & O_CREAT) || (flags & O_TMPFILE) == O_TMPFILE ? static_cast<mode_t>(va_arg(ap, int)) : 0;
}

// A camera path (absolute, or relative to AT_FDCWD: the emulation opens
// absolute paths only) opened as a device; -2 if it is none.
int openDevice(int dirfd, const char* path, int flags) {
  if (path == nullptr || path[0] != '/') return -2;
  (void)dirfd;  // an absolute path ignores it
  return v4::open(path, flags);
}

int openAt(const char* name, int dirfd, const char* path, int flags, mode_t mode) {
  const int fd = openDevice(dirfd, path, flags);
  if (fd != -2) return fd;
  static auto next = real<int (*)(int, const char*, int, ...)>(name);
  return next(dirfd, path, flags, mode);
}

int openPath(const char* name, const char* path, int flags, mode_t mode) {
  const int fd = openDevice(AT_FDCWD, path, flags);
  if (fd != -2) return fd;
  // One static per wrapper (name is a literal of the caller).
  static auto next_open = real<int (*)(const char*, int, ...)>("open");
  static auto next_open64 = real<int (*)(const char*, int, ...)>("open64");
  return (std::strcmp(name, "open64") == 0 ? next_open64 : next_open)(path, flags, mode);
}

void copyStat64(const struct stat& s, struct stat64* out) {
  std::memset(out, 0, sizeof *out);
  out->st_mode = s.st_mode;
  out->st_rdev = s.st_rdev;
  out->st_dev = s.st_dev;
  out->st_ino = s.st_ino;
  out->st_nlink = s.st_nlink;
  out->st_uid = s.st_uid;
  out->st_gid = s.st_gid;
  out->st_blksize = s.st_blksize;
}

void fillStat64(int fd, struct stat64* out) {
  struct stat s;
  v4::stat(fd, &s);
  copyStat64(s, out);
}

bool statPath64(const char* path, struct stat64* out) {
  struct stat s;
  if (!v4::statPath(path, &s)) return false;
  copyStat64(s, out);
  return true;
}

bool device(int fd) { return v4::anyOpen() && v4::isDevice(fd); }

}  // namespace

extern "C" {

SIMSWIFT_SHIM_EXPORT int open(const char* path, int flags, ...) {
  va_list ap;
  va_start(ap, flags);
  const mode_t mode = modeOf(flags, ap);
  va_end(ap);
  return openPath("open", path, flags, mode);
}

SIMSWIFT_SHIM_EXPORT int open64(const char* path, int flags, ...) {
  va_list ap;
  va_start(ap, flags);
  const mode_t mode = modeOf(flags, ap);
  va_end(ap);
  return openPath("open64", path, flags, mode);
}

SIMSWIFT_SHIM_EXPORT int __open_2(const char* path, int flags) { return openPath("open", path, flags, 0); }
SIMSWIFT_SHIM_EXPORT int __open64_2(const char* path, int flags) { return openPath("open64", path, flags, 0); }

SIMSWIFT_SHIM_EXPORT int openat(int dirfd, const char* path, int flags, ...) {
  va_list ap;
  va_start(ap, flags);
  const mode_t mode = modeOf(flags, ap);
  va_end(ap);
  return openAt("openat", dirfd, path, flags, mode);
}

SIMSWIFT_SHIM_EXPORT int openat64(int dirfd, const char* path, int flags, ...) {
  va_list ap;
  va_start(ap, flags);
  const mode_t mode = modeOf(flags, ap);
  va_end(ap);
  static auto next = real<int (*)(int, const char*, int, ...)>("openat64");
  const int fd = openDevice(dirfd, path, flags);
  return fd != -2 ? fd : next(dirfd, path, flags, mode);
}

SIMSWIFT_SHIM_EXPORT int __openat_2(int dirfd, const char* path, int flags) { return openAt("openat", dirfd, path, flags, 0); }
SIMSWIFT_SHIM_EXPORT int __openat64_2(int dirfd, const char* path, int flags) { return openat64(dirfd, path, flags); }

SIMSWIFT_SHIM_EXPORT int close(int fd) {
  static auto next = real<int (*)(int)>("close");
  if (device(fd)) v4::closing(fd);
  return next(fd);
}

SIMSWIFT_SHIM_EXPORT int ioctl(int fd, unsigned long request, ...) noexcept {
  va_list ap;
  va_start(ap, request);
  void* arg = va_arg(ap, void*);
  va_end(ap);
  if (v4::anyOpen()) {
    const int r = v4::ioctl(fd, request, arg);
    if (r != -2) return r;
  }
  static auto next = real<int (*)(int, unsigned long, ...)>("ioctl");
  return next(fd, request, arg);
}

SIMSWIFT_SHIM_EXPORT void* mmap(void* addr, size_t length, int prot, int flags, int fd, off_t offset) noexcept {
  if (fd >= 0 && !(flags & MAP_ANONYMOUS) && device(fd)) return v4::mmap(addr, length, prot, flags, fd, offset);
  static auto next = real<void* (*)(void*, size_t, int, int, int, off_t)>("mmap");
  return next(addr, length, prot, flags, fd, offset);
}

SIMSWIFT_SHIM_EXPORT void* mmap64(void* addr, size_t length, int prot, int flags, int fd, off64_t offset) noexcept {
  if (fd >= 0 && !(flags & MAP_ANONYMOUS) && device(fd)) return v4::mmap(addr, length, prot, flags, fd, offset);
  static auto next = real<void* (*)(void*, size_t, int, int, int, off64_t)>("mmap64");
  return next(addr, length, prot, flags, fd, offset);
}

// A NAO camera has no read() I/O (QUERYCAP gives no V4L2_CAP_READWRITE):
// EINVAL, as the kernel answers read on such a device.
SIMSWIFT_SHIM_EXPORT ssize_t read(int fd, void* buf, size_t count) {
  if (device(fd)) {
    errno = EINVAL;
    return -1;
  }
  static auto next = real<ssize_t (*)(int, void*, size_t)>("read");
  return next(fd, buf, count);
}

SIMSWIFT_SHIM_EXPORT int fstat(int fd, struct stat* out) noexcept {
  if (device(fd)) {
    v4::stat(fd, out);
    return 0;
  }
  static auto next = real<int (*)(int, struct stat*)>("fstat");
  return next(fd, out);
}

SIMSWIFT_SHIM_EXPORT int fstat64(int fd, struct stat64* out) noexcept {
  if (device(fd)) {
    fillStat64(fd, out);
    return 0;
  }
  static auto next = real<int (*)(int, struct stat64*)>("fstat64");
  return next(fd, out);
}

SIMSWIFT_SHIM_EXPORT int fstatat(int dirfd, const char* path, struct stat* out, int flags) noexcept {
  if ((flags & AT_EMPTY_PATH) && path[0] == '\0' && device(dirfd)) {
    v4::stat(dirfd, out);
    return 0;
  }
  if (v4::statPath(path, out)) return 0;  // absolute: dirfd does not matter
  static auto next = real<int (*)(int, const char*, struct stat*, int)>("fstatat");
  return next(dirfd, path, out, flags);
}

SIMSWIFT_SHIM_EXPORT int fstatat64(int dirfd, const char* path, struct stat64* out, int flags) noexcept {
  if ((flags & AT_EMPTY_PATH) && path[0] == '\0' && device(dirfd)) {
    fillStat64(dirfd, out);
    return 0;
  }
  if (statPath64(path, out)) return 0;
  static auto next = real<int (*)(int, const char*, struct stat64*, int)>("fstatat64");
  return next(dirfd, path, out, flags);
}

SIMSWIFT_SHIM_EXPORT int stat(const char* path, struct stat* out) noexcept {
  if (v4::statPath(path, out)) return 0;
  static auto next = real<int (*)(const char*, struct stat*)>("stat");
  return next(path, out);
}
SIMSWIFT_SHIM_EXPORT int stat64(const char* path, struct stat64* out) noexcept {
  if (statPath64(path, out)) return 0;
  static auto next = real<int (*)(const char*, struct stat64*)>("stat64");
  return next(path, out);
}
SIMSWIFT_SHIM_EXPORT int lstat(const char* path, struct stat* out) noexcept {
  if (v4::statPath(path, out)) return 0;
  static auto next = real<int (*)(const char*, struct stat*)>("lstat");
  return next(path, out);
}
SIMSWIFT_SHIM_EXPORT int lstat64(const char* path, struct stat64* out) noexcept {
  if (statPath64(path, out)) return 0;
  static auto next = real<int (*)(const char*, struct stat64*)>("lstat64");
  return next(path, out);
}

// Binaries built against glibc before 2.33 call these (version 1: the
// kernel's struct stat, which is glibc's on x86_64 and arm64).
SIMSWIFT_SHIM_EXPORT int __fxstat(int ver, int fd, struct stat* out) {
  (void)ver;
  return fstat(fd, out);
}
SIMSWIFT_SHIM_EXPORT int __fxstat64(int ver, int fd, struct stat64* out) {
  (void)ver;
  return fstat64(fd, out);
}

SIMSWIFT_SHIM_EXPORT int __xstat(int ver, const char* path, struct stat* out) {
  (void)ver;
  return stat(path, out);
}
SIMSWIFT_SHIM_EXPORT int __xstat64(int ver, const char* path, struct stat64* out) {
  (void)ver;
  return stat64(path, out);
}
SIMSWIFT_SHIM_EXPORT int __lxstat(int ver, const char* path, struct stat* out) {
  (void)ver;
  return lstat(path, out);
}
SIMSWIFT_SHIM_EXPORT int __lxstat64(int ver, const char* path, struct stat64* out) {
  (void)ver;
  return lstat64(path, out);
}

}  // extern "C"
