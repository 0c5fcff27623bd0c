// The NAO's cameras as the shim's V4L2 devices (docs/porting.md section 3):
// what a program's open/ioctl/mmap/close/fstat/read of /dev/video-top become
// (the wrappers: V4l2Wrappers.cpp). Frames come from the simulator through
// common/v4l2/DeviceBlock.hpp; a device's fd is the read end of the block's
// FIFO for that camera, readable while a frame waits, so poll, select and
// epoll on it work in the kernel, unchanged.
//
// Everything here runs under one lock; no exception leaves it (errors are
// errno values, as the kernel gives them).
#pragma once

#include <sys/stat.h>
#include <sys/types.h>

#include <cstddef>

namespace simswift::shim::v4l2 {

// Whether any camera fd is open (one atomic load): the wrappers' fast path
// for every other fd.
bool anyOpen();
// `path` names one of the robot's cameras (the block's device paths):
// opens it and returns the program's fd, or -1 with errno. Returns -2 if
// `path` is not a camera (the caller opens it as usual).
int open(const char* path, int flags);
// `path` names one of the robot's cameras: what stat says of it (a
// character device, as stat(fd) below). False if it is none.
bool statPath(const char* path, struct stat* out);
// fd is a camera fd (the caller checks anyOpen() first).
bool isDevice(int fd);
// VIDIOC_* and UVCIOC_CTRL_QUERY: 0 or -1 with errno.
int ioctl(int fd, unsigned long request, void* arg);
// The MMAP buffer at `offset` mapped (MAP_FAILED with errno if none).
void* mmap(void* addr, size_t length, int prot, int flags, int fd, off_t offset);
// What fstat says of a camera: a character device (video4linux's major 81).
void stat(int fd, struct stat* out);
// The fd is closed by the program: its camera stops streaming when it was
// the camera's last fd. The caller closes the fd itself.
void closing(int fd);

}  // namespace simswift::shim::v4l2
