#include "shim/V4l2Device.hpp"

#include "common/clock/ClockPage.hpp"

#include <fcntl.h>
#include <linux/usb/video.h>
#include <linux/uvcvideo.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "common/v4l2/DeviceBlock.hpp"
#include "shim/Real.hpp"

namespace simswift::shim::v4l2 {

namespace {

namespace cv = common::v4l2;

// libc's functions, not the shim's own (a call from here to `open` would
// come back to the wrapper).
struct Libc {
  int (*open)(const char*, int, ...) = real<int (*)(const char*, int, ...)>("open");
  int (*close)(int) = real<int (*)(int)>("close");
  int (*ioctl)(int, unsigned long, ...) = real<int (*)(int, unsigned long, ...)>("ioctl");
  ssize_t (*read)(int, void*, size_t) = real<ssize_t (*)(int, void*, size_t)>("read");
  void* (*mmap)(void*, size_t, int, int, int, off_t) = real<void* (*)(void*, size_t, int, int, int, off_t)>("mmap");
  int (*poll)(pollfd*, nfds_t, int) = real<int (*)(pollfd*, nfds_t, int)>("poll");
};
const Libc& libc() {
  static const Libc l;
  return l;
}

constexpr uint32_t kYuyv = V4L2_PIX_FMT_YUYV;
constexpr size_t kPage = 4096;
// QUERYBUF's m.offset of buffer i: i * kOffsetStride (page aligned, as mmap needs).
constexpr uint32_t kOffsetStride = 1u << 24;

// The controls a NAO camera lists (QUERYCTRL), with ranges wide enough for
// every team's settings in facts.md section 10: a program clamps to them.
struct ControlInfo {
  uint32_t id;
  uint32_t type;
  const char* name;
  int32_t min, max, step, def;
};
constexpr ControlInfo kControls[] = {
    {V4L2_CID_BRIGHTNESS, V4L2_CTRL_TYPE_INTEGER, "Brightness", -255, 255, 1, 0},
    {V4L2_CID_CONTRAST, V4L2_CTRL_TYPE_INTEGER, "Contrast", 0, 255, 1, 32},
    {V4L2_CID_SATURATION, V4L2_CTRL_TYPE_INTEGER, "Saturation", 0, 255, 1, 64},
    {V4L2_CID_HUE, V4L2_CTRL_TYPE_INTEGER, "Hue", -180, 180, 1, 0},
    {V4L2_CID_AUTO_WHITE_BALANCE, V4L2_CTRL_TYPE_BOOLEAN, "White Balance Temperature, Auto", 0, 1, 1, 1},
    {V4L2_CID_GAMMA, V4L2_CTRL_TYPE_INTEGER, "Gamma", 100, 300, 1, 220},
    {V4L2_CID_GAIN, V4L2_CTRL_TYPE_INTEGER, "Gain", 0, 1023, 1, 32},
    {V4L2_CID_POWER_LINE_FREQUENCY, V4L2_CTRL_TYPE_MENU, "Power Line Frequency", 0, 2, 1, 1},
    {V4L2_CID_HFLIP, V4L2_CTRL_TYPE_BOOLEAN, "Horizontal Flip", 0, 1, 1, 0},
    {V4L2_CID_VFLIP, V4L2_CTRL_TYPE_BOOLEAN, "Vertical Flip", 0, 1, 1, 0},
    {V4L2_CID_WHITE_BALANCE_TEMPERATURE, V4L2_CTRL_TYPE_INTEGER, "White Balance Temperature", 2500, 6500, 1, 6500},
    {V4L2_CID_SHARPNESS, V4L2_CTRL_TYPE_INTEGER, "Sharpness", 0, 255, 1, 0},
    {V4L2_CID_BACKLIGHT_COMPENSATION, V4L2_CTRL_TYPE_INTEGER, "Backlight Compensation", 0, 4, 1, 1},
    {V4L2_CID_EXPOSURE_AUTO, V4L2_CTRL_TYPE_MENU, "Exposure, Auto", 0, 3, 1, 0},
    {V4L2_CID_EXPOSURE_ABSOLUTE, V4L2_CTRL_TYPE_INTEGER, "Exposure (Absolute)", 0, 1048575, 1, 512},
    {V4L2_CID_FOCUS_ABSOLUTE, V4L2_CTRL_TYPE_INTEGER, "Focus (absolute)", 0, 250, 1, 0},
    {V4L2_CID_FOCUS_AUTO, V4L2_CTRL_TYPE_BOOLEAN, "Focus, Auto", 0, 1, 1, 0},
};  // ascending ids (QUERYCTRL's NEXT_CTRL walks them in order)

const ControlInfo* control(uint32_t id) {
  for (const ControlInfo& c : kControls)
    if (c.id == id) return &c;
  return nullptr;
}

const char* menuName(uint32_t id, uint32_t index) {
  if (id == V4L2_CID_EXPOSURE_AUTO) {
    static const char* const n[] = {"Auto Mode", "Manual Mode", "Shutter Priority Mode", "Aperture Priority Mode"};
    return index < 4 ? n[index] : nullptr;
  }
  if (id == V4L2_CID_POWER_LINE_FREQUENCY) {
    static const char* const n[] = {"Disabled", "50 Hz", "60 Hz"};
    return index < 3 ? n[index] : nullptr;
  }
  return nullptr;
}

struct Buffer {
  int memfd = -1;            // MMAP: the buffer's memory (the program maps it through mmap)
  uint8_t* data = nullptr;   // MMAP: the shim's own mapping of it
  size_t length = 0;         // bytes (MMAP: sizeimage rounded up to pages)
  unsigned long userptr = 0; // USERPTR: the program's memory, given at QBUF
  size_t user_length = 0;
  bool queued = false;
  // The last frame it held (QUERYBUF reports it).
  uint32_t bytesused = 0, sequence = 0;
  timeval timestamp{};
};

struct Camera {
  int index = 0;  // 0 top, 1 bottom
  int fds = 0;    // the program's fds open on it
  cv::FrameSize size = cv::kDefaultFrameSize;
  uint32_t memory = 0;  // V4L2_MEMORY_MMAP / USERPTR once REQBUFS gave buffers, else 0
  std::vector<Buffer> buffers;
  std::deque<int> queue;  // queued buffers, oldest first
  bool streaming = false;
  int64_t taken = 0;      // frames_posted of the last frame dequeued
  uint32_t sequence = 0;  // frames dequeued since STREAMON
  std::map<uint32_t, int64_t> controls;  // set values (unset: the default)
  v4l2_rect crop{0, 0, 0, 0};
  v4l2_std_id standard = 0;
  // UVC extension unit registers: (unit, selector) -> bytes (SET_CUR kept, GET_CUR read back).
  std::map<std::pair<uint8_t, uint8_t>, std::vector<uint8_t>> xu;
  std::map<uint16_t, uint16_t> registers;  // selector 14's register file (address -> value)
};

struct State {
  std::mutex lock;
  bool tried = false;
  cv::DeviceBlock* block = nullptr;
  std::string name;
  int taken_fd = -1;  // the "taken" FIFO (O_RDWR: writing never raises SIGPIPE)
  Camera camera[cv::kNumCameras];
  std::map<int, int> fds;  // program fd -> camera
  std::set<unsigned long> noted;  // unknown requests already reported
};
State& state() {
  static State* s = new State;  // never destroyed: a program's threads may call in during exit
  return *s;
}
std::atomic<int> open_count{0};

// The block named by the environment, mapped once (first camera open).
// False, with a line on stderr, if the variable is set but the block is not
// a simswift block.
bool attach(State& s) {
  if (s.tried) return s.block != nullptr;
  s.tried = true;
  const char* name = std::getenv(cv::kBlockVariable);
  if (name == nullptr || name[0] != '/') return false;
  s.name = name;
  const int fd = shm_open(name, O_RDWR | O_CLOEXEC, 0);
  if (fd < 0) {
    std::fprintf(stderr, "simswift shim: cannot open the camera block %s (%s): no cameras\n", name, std::strerror(errno));
    return false;
  }
  void* p = libc().mmap(nullptr, sizeof(cv::DeviceBlock), PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  libc().close(fd);
  auto* b = static_cast<cv::DeviceBlock*>(p);
  if (p == MAP_FAILED || b->magic.load(std::memory_order_acquire) != cv::kBlockMagic || b->version != cv::kBlockVersion) {
    std::fprintf(stderr, "simswift shim: %s is not a simswift camera block of version %u: no cameras\n", name,
                 cv::kBlockVersion);
    return false;
  }
  s.taken_fd = libc().open(cv::fifoPath(s.name, cv::kTakenFifo).c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
  if (s.taken_fd < 0) {
    std::fprintf(stderr, "simswift shim: cannot open the camera FIFO of %s (%s): no cameras\n", name,
                 std::strerror(errno));
    return false;
  }
  s.block = b;
  for (int c = 0; c < cv::kNumCameras; ++c) s.camera[c].index = c;
  return true;
}

int fail(int e) {
  errno = e;
  return -1;
}

uint32_t sizeImage(const Camera& c) { return static_cast<uint32_t>(c.size.width * c.size.height * 2); }

cv::FrameSize snap(uint32_t w, uint32_t h) {
  cv::FrameSize best = cv::kFrameSizes[0];
  for (const cv::FrameSize& s : cv::kFrameSizes)
    if (uint32_t(s.width) <= w && uint32_t(s.height) <= h) best = s;
  return best;
}

void fillFormat(const cv::FrameSize& size, v4l2_format* f) {
  std::memset(&f->fmt.pix, 0, sizeof f->fmt.pix);
  f->type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  f->fmt.pix.width = static_cast<uint32_t>(size.width);
  f->fmt.pix.height = static_cast<uint32_t>(size.height);
  f->fmt.pix.pixelformat = kYuyv;
  f->fmt.pix.field = V4L2_FIELD_NONE;
  f->fmt.pix.bytesperline = static_cast<uint32_t>(size.width * 2);
  f->fmt.pix.sizeimage = static_cast<uint32_t>(size.width * size.height * 2);
  f->fmt.pix.colorspace = V4L2_COLORSPACE_JPEG;  // BT.601 full range (CameraImages.hpp)
}

// Everything the FIFO holds read (FIONREAD: never blocks, whatever the fd's flags).
void drain(int fd) {
  int n = 0;
  char buffer[256];
  while (libc().ioctl(fd, FIONREAD, &n) == 0 && n > 0)
    if (libc().read(fd, buffer, std::min<size_t>(sizeof buffer, size_t(n))) <= 0) break;
}

void freeBuffers(Camera& c) {
  for (Buffer& b : c.buffers) {
    if (b.data) munmap(b.data, b.length);
    if (b.memfd >= 0) libc().close(b.memfd);
  }
  c.buffers.clear();
  c.queue.clear();
  c.memory = 0;
}

void publishQueue(State& s, Camera& c) {
  s.block->camera[c.index].buffers_queued.store(c.streaming ? static_cast<int32_t>(c.queue.size()) : 0,
                                                std::memory_order_release);
}

void streamOff(State& s, Camera& c) {
  c.streaming = false;
  c.queue.clear();
  for (Buffer& b : c.buffers) b.queued = false;
  s.block->camera[c.index].streaming.store(0, std::memory_order_release);
  publishQueue(s, c);
}

void describe(const Camera& c, int index, v4l2_buffer* b) {
  const Buffer& buf = c.buffers[static_cast<size_t>(index)];
  b->index = static_cast<uint32_t>(index);
  b->type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  b->memory = c.memory;
  b->bytesused = buf.bytesused;
  b->field = V4L2_FIELD_NONE;
  b->sequence = buf.sequence;
  b->timestamp = buf.timestamp;
  b->flags = V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | V4L2_BUF_FLAG_TSTAMP_SRC_SOE;
  if (c.memory == V4L2_MEMORY_MMAP) {
    b->flags |= V4L2_BUF_FLAG_MAPPED;
    b->m.offset = static_cast<uint32_t>(index) * kOffsetStride;
    b->length = static_cast<uint32_t>(buf.length);
  } else {
    b->m.userptr = buf.userptr;
    b->length = static_cast<uint32_t>(buf.user_length);
  }
  if (buf.queued) b->flags |= V4L2_BUF_FLAG_QUEUED;
}

int reqbufs(State& s, Camera& c, v4l2_requestbuffers* r) {
  if (r->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
  if (r->memory != V4L2_MEMORY_MMAP && r->memory != V4L2_MEMORY_USERPTR) return fail(EINVAL);
  r->capabilities = V4L2_BUF_CAP_SUPPORTS_MMAP | V4L2_BUF_CAP_SUPPORTS_USERPTR;
  if (c.streaming) return fail(EBUSY);
  freeBuffers(c);
  if (r->count == 0) return 0;
  const uint32_t count = std::min<uint32_t>(r->count, cv::kMaxBuffers);
  c.buffers.resize(count);
  const size_t length = (sizeImage(c) + kPage - 1) / kPage * kPage;
  for (Buffer& b : c.buffers) {
    if (r->memory == V4L2_MEMORY_MMAP) {
      b.memfd = memfd_create("simswift-v4l2-buffer", MFD_CLOEXEC);
      if (b.memfd < 0 || ftruncate(b.memfd, static_cast<off_t>(length)) != 0) {
        const int e = errno;
        freeBuffers(c);
        return fail(e == 0 ? ENOMEM : e);
      }
      void* p = libc().mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_SHARED, b.memfd, 0);
      if (p == MAP_FAILED) {
        const int e = errno;
        freeBuffers(c);
        return fail(e);
      }
      b.data = static_cast<uint8_t*>(p);
      b.length = length;
    }
  }
  c.memory = r->memory;
  r->count = count;
  publishQueue(s, c);
  return 0;
}

int qbuf(State& s, Camera& c, v4l2_buffer* b) {
  if (b->type != V4L2_BUF_TYPE_VIDEO_CAPTURE || b->memory != c.memory || c.memory == 0 ||
      b->index >= c.buffers.size())
    return fail(EINVAL);
  Buffer& buf = c.buffers[b->index];
  if (buf.queued) return fail(EINVAL);
  if (c.memory == V4L2_MEMORY_USERPTR) {
    if (b->m.userptr == 0 || b->length < sizeImage(c)) return fail(EINVAL);
    buf.userptr = b->m.userptr;
    buf.user_length = b->length;
  }
  buf.queued = true;
  c.queue.push_back(static_cast<int>(b->index));
  describe(c, static_cast<int>(b->index), b);
  publishQueue(s, c);
  return 0;
}

// The frame published to camera c, if one is new and a buffer is queued:
// copied into the oldest queued buffer, which is handed back in `b`; the
// simulator told it was taken. EAGAIN if none.
int takeFrame(State& s, Camera& c, int fd, v4l2_buffer* b) {
  cv::CameraChannel& ch = s.block->camera[c.index];
  drain(fd);
  const int64_t posted = ch.frames_posted.load(std::memory_order_acquire);
  if (posted <= c.taken || c.queue.empty()) return fail(EAGAIN);
  const int index = c.queue.front();
  c.queue.pop_front();
  Buffer& buf = c.buffers[static_cast<size_t>(index)];
  uint8_t* to = c.memory == V4L2_MEMORY_MMAP ? buf.data : reinterpret_cast<uint8_t*>(buf.userptr);
  const size_t room = c.memory == V4L2_MEMORY_MMAP ? buf.length : buf.user_length;
  // The simulator's numbers, bounded by the block and the buffer.
  const int64_t w = std::clamp<int64_t>(ch.width, 0, common::libagent::kMaxImageWidth);
  const int64_t h = std::clamp<int64_t>(ch.height, 0, common::libagent::kMaxImageHeight);
  const size_t bytes = std::min<size_t>(static_cast<size_t>(w * h * 2), room);
  std::memcpy(to, ch.image, bytes);
  buf.queued = false;
  buf.bytesused = static_cast<uint32_t>(bytes);
  buf.sequence = c.sequence++;
  // The frame's own simulated time, as the program's CLOCK_MONOTONIC reads
  // it (the clock page's base: kMonotonicStartNs + the run's time), as a
  // UVC driver stamps its buffers (TIMESTAMP_MONOTONIC): NaoTH compares the
  // two and warns when they differ.
  const int64_t t_us = common::clock::kMonotonicStartNs / 1000 + ch.sim_time_us;
  buf.timestamp.tv_sec = static_cast<time_t>(t_us / 1000000);
  buf.timestamp.tv_usec = static_cast<suseconds_t>(t_us % 1000000);
  c.taken = posted;
  ch.frames_taken.store(posted, std::memory_order_release);
  publishQueue(s, c);
  const char byte = 1;
  ssize_t n = write(s.taken_fd, &byte, 1);  // wakes the simulator's lock-step wait
  (void)n;
  describe(c, index, b);
  b->flags |= V4L2_BUF_FLAG_DONE;
  b->flags &= ~static_cast<uint32_t>(V4L2_BUF_FLAG_QUEUED);
  return 0;
}

int dqbuf(State& s, std::unique_lock<std::mutex>& held, Camera& c, int fd, v4l2_buffer* b) {
  if (b->type != V4L2_BUF_TYPE_VIDEO_CAPTURE || b->memory != c.memory) return fail(EINVAL);
  for (;;) {
    if (s.block->shutdown.load(std::memory_order_acquire)) return fail(ENODEV);
    if (!c.streaming) return fail(EINVAL);
    if (takeFrame(s, c, fd, b) == 0) return 0;
    const int flags = fcntl(fd, F_GETFL);
    if (flags >= 0 && (flags & O_NONBLOCK)) return fail(EAGAIN);
    // Blocking: wait for the FIFO (the next frame) without the lock; a
    // slice, so a shutdown or STREAMOFF from another thread is seen.
    held.unlock();
    pollfd p{fd, POLLIN, 0};
    libc().poll(&p, 1, 100);
    held.lock();
  }
}

int queryctrl(Camera& c, v4l2_queryctrl* q) {
  (void)c;
  const ControlInfo* info = nullptr;
  if (q->id & V4L2_CTRL_FLAG_NEXT_CTRL) {
    const uint32_t after = q->id & ~(V4L2_CTRL_FLAG_NEXT_CTRL | V4L2_CTRL_FLAG_NEXT_COMPOUND);
    for (const ControlInfo& k : kControls)
      if (k.id > after) {
        info = &k;
        break;
      }
  } else {
    info = control(q->id);
  }
  if (!info) return fail(EINVAL);
  std::memset(q, 0, sizeof *q);
  q->id = info->id;
  q->type = info->type;
  std::strncpy(reinterpret_cast<char*>(q->name), info->name, sizeof q->name - 1);
  q->minimum = info->min;
  q->maximum = info->max;
  q->step = info->step;
  q->default_value = info->def;
  return 0;
}

// Any control id is kept and read back as set (a control the camera lists
// starts at its default, any other at 0): a program that retries S_CTRL
// until G_CTRL reads its value back (rUNSWift) never spins, and a value out
// of QUERYCTRL's range is the program's own (the picture does not change
// with the controls).
int getControl(const Camera& c, uint32_t id, int64_t* value) {
  const auto it = c.controls.find(id);
  const ControlInfo* info = control(id);
  *value = it != c.controls.end() ? it->second : info ? info->def : 0;
  return 0;
}

int setControl(Camera& c, uint32_t id, int64_t* value, bool store) {
  if (store) c.controls[id] = *value;
  return 0;
}

int extControls(Camera& c, unsigned long request, v4l2_ext_controls* x) {
  if (x->count > 1024 || (x->count > 0 && x->controls == nullptr)) return fail(EINVAL);
  // Checked first (all or none), then applied.
  for (uint32_t i = 0; i < x->count; ++i) {
    if (x->controls[i].size != 0) {  // a compound control (a pointer payload): none is emulated
      x->error_idx = i;
      return fail(EINVAL);
    }
  }
  for (uint32_t i = 0; i < x->count; ++i) {
    v4l2_ext_control& e = x->controls[i];
    int64_t v = e.value;
    if (request == VIDIOC_G_EXT_CTRLS) getControl(c, e.id, &v);
    else setControl(c, e.id, &v, request == VIDIOC_S_EXT_CTRLS);
    e.value = static_cast<int32_t>(v);
  }
  return 0;
}

// UVC extension-unit queries (uvcvideo's UVCIOC_CTRL_QUERY): every unit and
// selector answered; SET_CUR's bytes kept and read back by GET_CUR. Selector
// 14 of unit 3 is the NAO's register access (B-Human, rUNSWift: [flag,
// address high, address low, value high, value low], flag 1 writes): the
// register file is kept, a read request (flag 0) is answered from it.
int uvcQuery(Camera& c, uvc_xu_control_query* q) {
  if (q->size > 0 && q->data == nullptr) return fail(EFAULT);
  std::vector<uint8_t>& kept = c.xu[{q->unit, q->selector}];
  const bool registers = q->unit == 3 && q->selector == 14;
  switch (q->query) {
    case UVC_SET_CUR:
      kept.assign(q->data, q->data + q->size);
      if (registers && q->size >= 5) {
        const uint16_t address = static_cast<uint16_t>(q->data[1] << 8 | q->data[2]);
        if (q->data[0] == 1) c.registers[address] = static_cast<uint16_t>(q->data[3] << 8 | q->data[4]);
      }
      return 0;
    case UVC_GET_CUR:
      std::memset(q->data, 0, q->size);
      std::memcpy(q->data, kept.data(), std::min<size_t>(kept.size(), q->size));
      if (registers && q->size >= 5) {
        const uint16_t address = static_cast<uint16_t>(q->data[1] << 8 | q->data[2]);
        const uint16_t value = c.registers.count(address) ? c.registers[address] : 0;
        q->data[3] = static_cast<uint8_t>(value >> 8);
        q->data[4] = static_cast<uint8_t>(value & 0xff);
      }
      return 0;
    case UVC_GET_LEN:
      if (q->size < 2) return fail(EINVAL);
      q->data[0] = static_cast<uint8_t>(kept.empty() ? q->size : kept.size());
      q->data[1] = 0;
      return 0;
    case UVC_GET_INFO:
      if (q->size < 1) return fail(EINVAL);
      q->data[0] = 0x03;  // supports GET and SET
      return 0;
    case UVC_GET_MIN:
    case UVC_GET_DEF:
      std::memset(q->data, 0, q->size);
      return 0;
    case UVC_GET_MAX:
      std::memset(q->data, 0xff, q->size);
      return 0;
    case UVC_GET_RES:
      std::memset(q->data, 0, q->size);
      if (q->size > 0) q->data[0] = 1;
      return 0;
    default:
      return fail(EINVAL);
  }
}

// The requests handle() answers (a null argument to one of them is EFAULT,
// to any other ENOTTY, as the kernel checks the request first).
bool known(unsigned long request) {
  switch (request) {
    case VIDIOC_QUERYCAP: case VIDIOC_ENUM_FMT: case VIDIOC_ENUM_FRAMESIZES: case VIDIOC_ENUM_FRAMEINTERVALS:
    case VIDIOC_G_FMT: case VIDIOC_TRY_FMT: case VIDIOC_S_FMT: case VIDIOC_G_PARM: case VIDIOC_S_PARM:
    case VIDIOC_CROPCAP: case VIDIOC_G_CROP: case VIDIOC_S_CROP: case VIDIOC_ENUMINPUT: case VIDIOC_G_INPUT:
    case VIDIOC_S_INPUT: case VIDIOC_G_STD: case VIDIOC_S_STD: case VIDIOC_REQBUFS: case VIDIOC_QUERYBUF:
    case VIDIOC_QBUF: case VIDIOC_DQBUF: case VIDIOC_STREAMON: case VIDIOC_STREAMOFF: case VIDIOC_QUERYCTRL:
    case VIDIOC_QUERYMENU: case VIDIOC_G_CTRL: case VIDIOC_S_CTRL: case VIDIOC_G_EXT_CTRLS:
    case VIDIOC_S_EXT_CTRLS: case VIDIOC_TRY_EXT_CTRLS: case UVCIOC_CTRL_QUERY:
      return true;
    default:
      return false;
  }
}

int handle(State& s, std::unique_lock<std::mutex>& held, int fd, Camera& c, unsigned long request, void* arg) {
  if (arg == nullptr && known(request)) return fail(EFAULT);
  switch (request) {
    case VIDIOC_QUERYCAP: {
      auto* cap = static_cast<v4l2_capability*>(arg);
      std::memset(cap, 0, sizeof *cap);
      std::strncpy(reinterpret_cast<char*>(cap->driver), "uvcvideo", sizeof cap->driver - 1);
      std::snprintf(reinterpret_cast<char*>(cap->card), sizeof cap->card, "simswift NAO %s camera",
                    cv::cameraFifo(c.index));
      std::snprintf(reinterpret_cast<char*>(cap->bus_info), sizeof cap->bus_info, "usb-simswift-%d", c.index + 1);
      cap->version = 0x060100;
      cap->device_caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
      cap->capabilities = cap->device_caps | V4L2_CAP_DEVICE_CAPS;
      return 0;
    }
    case VIDIOC_ENUM_FMT: {
      auto* f = static_cast<v4l2_fmtdesc*>(arg);
      if (f->type != V4L2_BUF_TYPE_VIDEO_CAPTURE || f->index != 0) return fail(EINVAL);
      const uint32_t index = f->index;
      std::memset(f, 0, sizeof *f);
      f->index = index;
      f->type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
      std::strncpy(reinterpret_cast<char*>(f->description), "YUYV 4:2:2", sizeof f->description - 1);
      f->pixelformat = kYuyv;
      return 0;
    }
    case VIDIOC_ENUM_FRAMESIZES: {
      auto* f = static_cast<v4l2_frmsizeenum*>(arg);
      constexpr uint32_t n = sizeof cv::kFrameSizes / sizeof cv::kFrameSizes[0];
      if (f->pixel_format != kYuyv || f->index >= n) return fail(EINVAL);
      f->type = V4L2_FRMSIZE_TYPE_DISCRETE;
      f->discrete.width = static_cast<uint32_t>(cv::kFrameSizes[f->index].width);
      f->discrete.height = static_cast<uint32_t>(cv::kFrameSizes[f->index].height);
      return 0;
    }
    case VIDIOC_ENUM_FRAMEINTERVALS: {
      auto* f = static_cast<v4l2_frmivalenum*>(arg);
      if (f->pixel_format != kYuyv || f->index != 0 || !cv::isFrameSize(int32_t(f->width), int32_t(f->height)))
        return fail(EINVAL);
      f->type = V4L2_FRMIVAL_TYPE_DISCRETE;
      f->discrete = {1, 30};
      return 0;
    }
    case VIDIOC_G_FMT: {
      auto* f = static_cast<v4l2_format*>(arg);
      if (f->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
      fillFormat(c.size, f);
      return 0;
    }
    case VIDIOC_TRY_FMT:
    case VIDIOC_S_FMT: {
      auto* f = static_cast<v4l2_format*>(arg);
      if (f->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
      const cv::FrameSize size = snap(f->fmt.pix.width, f->fmt.pix.height);
      if (request == VIDIOC_S_FMT) {
        if (!c.buffers.empty()) return fail(EBUSY);
        c.size = size;
        c.crop = {0, 0, static_cast<uint32_t>(size.width), static_cast<uint32_t>(size.height)};
        s.block->camera[c.index].width_wanted.store(size.width, std::memory_order_release);
        s.block->camera[c.index].height_wanted.store(size.height, std::memory_order_release);
      }
      fillFormat(size, f);  // any other pixel format or field: adjusted to YUYV, progressive
      return 0;
    }
    case VIDIOC_G_PARM:
    case VIDIOC_S_PARM: {
      auto* p = static_cast<v4l2_streamparm*>(arg);
      if (p->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
      // 30 Hz of simulated time, whatever is asked (the NAO's rate).
      std::memset(&p->parm.capture, 0, sizeof p->parm.capture);
      p->parm.capture.capability = V4L2_CAP_TIMEPERFRAME;
      p->parm.capture.timeperframe = {1, 30};
      p->parm.capture.readbuffers = 0;
      return 0;
    }
    case VIDIOC_CROPCAP: {
      auto* cc = static_cast<v4l2_cropcap*>(arg);
      if (cc->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
      cc->bounds = {0, 0, static_cast<uint32_t>(c.size.width), static_cast<uint32_t>(c.size.height)};
      cc->defrect = cc->bounds;
      cc->pixelaspect = {1, 1};
      return 0;
    }
    case VIDIOC_G_CROP: {
      auto* cr = static_cast<v4l2_crop*>(arg);
      if (cr->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
      cr->c = c.crop.width ? c.crop : v4l2_rect{0, 0, uint32_t(c.size.width), uint32_t(c.size.height)};
      return 0;
    }
    case VIDIOC_S_CROP: {
      // Kept and read back; the image is always the whole field of view.
      auto* cr = static_cast<const v4l2_crop*>(arg);
      if (cr->type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
      c.crop = cr->c;
      return 0;
    }
    case VIDIOC_ENUMINPUT: {
      auto* in = static_cast<v4l2_input*>(arg);
      if (in->index != 0) return fail(EINVAL);
      std::memset(in, 0, sizeof *in);
      std::strncpy(reinterpret_cast<char*>(in->name), "Camera 1", sizeof in->name - 1);
      in->type = V4L2_INPUT_TYPE_CAMERA;
      return 0;
    }
    case VIDIOC_G_INPUT:
      *static_cast<int*>(arg) = 0;
      return 0;
    case VIDIOC_S_INPUT:
      return *static_cast<const int*>(arg) == 0 ? 0 : fail(EINVAL);
    case VIDIOC_G_STD:
      *static_cast<v4l2_std_id*>(arg) = c.standard;
      return 0;
    case VIDIOC_S_STD:
      c.standard = *static_cast<const v4l2_std_id*>(arg);  // kept, read back (a camera has no TV standard)
      return 0;
    case VIDIOC_REQBUFS:
      return reqbufs(s, c, static_cast<v4l2_requestbuffers*>(arg));
    case VIDIOC_QUERYBUF: {
      auto* b = static_cast<v4l2_buffer*>(arg);
      if (b->type != V4L2_BUF_TYPE_VIDEO_CAPTURE || b->index >= c.buffers.size()) return fail(EINVAL);
      describe(c, static_cast<int>(b->index), b);
      return 0;
    }
    case VIDIOC_QBUF:
      return qbuf(s, c, static_cast<v4l2_buffer*>(arg));
    case VIDIOC_DQBUF:
      return dqbuf(s, held, c, fd, static_cast<v4l2_buffer*>(arg));
    case VIDIOC_STREAMON: {
      if (*static_cast<const int*>(arg) != V4L2_BUF_TYPE_VIDEO_CAPTURE || c.buffers.empty()) return fail(EINVAL);
      if (c.streaming) return 0;
      cv::CameraChannel& ch = s.block->camera[c.index];
      c.streaming = true;
      c.sequence = 0;
      c.taken = ch.frames_posted.load(std::memory_order_acquire);  // frames from now on
      drain(fd);
      publishQueue(s, c);
      ch.streaming.store(1, std::memory_order_release);
      return 0;
    }
    case VIDIOC_STREAMOFF:
      if (*static_cast<const int*>(arg) != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
      streamOff(s, c);
      drain(fd);
      return 0;
    case VIDIOC_QUERYCTRL:
      return queryctrl(c, static_cast<v4l2_queryctrl*>(arg));
    case VIDIOC_QUERYMENU: {
      auto* m = static_cast<v4l2_querymenu*>(arg);
      const char* name = menuName(m->id, m->index);
      if (!name) return fail(EINVAL);
      std::memset(m->name, 0, sizeof m->name);
      std::strncpy(reinterpret_cast<char*>(m->name), name, sizeof m->name - 1);
      return 0;
    }
    case VIDIOC_G_CTRL: {
      auto* ctl = static_cast<v4l2_control*>(arg);
      int64_t v = 0;
      if (getControl(c, ctl->id, &v) != 0) return -1;
      ctl->value = static_cast<int32_t>(v);
      return 0;
    }
    case VIDIOC_S_CTRL: {
      auto* ctl = static_cast<v4l2_control*>(arg);
      int64_t v = ctl->value;
      if (setControl(c, ctl->id, &v, true) != 0) return -1;
      ctl->value = static_cast<int32_t>(v);
      return 0;
    }
    case VIDIOC_G_EXT_CTRLS:
    case VIDIOC_S_EXT_CTRLS:
    case VIDIOC_TRY_EXT_CTRLS:
      return extControls(c, request, static_cast<v4l2_ext_controls*>(arg));
    case UVCIOC_CTRL_QUERY:
      return uvcQuery(c, static_cast<uvc_xu_control_query*>(arg));
    default:
      break;
  }
  // Not emulated: ENOTTY, what the kernel answers a request a driver does
  // not know; said once per request on stderr.
  if (s.noted.insert(request).second)
    std::fprintf(stderr, "simswift shim: %s: ioctl request 0x%lx is not emulated (ENOTTY)\n",
                 s.block->camera[c.index].device, request);
  return fail(ENOTTY);
}

}  // namespace

bool anyOpen() { return open_count.load(std::memory_order_acquire) > 0; }

int open(const char* path, int flags) {
  if (path == nullptr || std::strncmp(path, "/dev/", 5) != 0) return -2;
  State& s = state();
  std::lock_guard<std::mutex> g(s.lock);
  if (!attach(s)) return -2;
  int camera = -1;
  for (int c = 0; c < cv::kNumCameras; ++c)
    if (std::strncmp(path, s.block->camera[c].device, cv::kMaxDevicePath) == 0) camera = c;
  if (camera < 0) return -2;
  // The camera's fd: the read end of its FIFO (O_RDWR: a FIFO so opened
  // never blocks and never sees a hang-up), with the program's O_NONBLOCK
  // and O_CLOEXEC.
  const int fd = libc().open(cv::fifoPath(s.name, cv::cameraFifo(camera)).c_str(),
                             O_RDWR | (flags & (O_NONBLOCK | O_CLOEXEC)));
  if (fd < 0) return -1;
  s.fds[fd] = camera;
  ++s.camera[camera].fds;
  open_count.fetch_add(1, std::memory_order_release);
  return fd;
}

namespace {
void fillStat(int camera, struct stat* out) {
  std::memset(out, 0, sizeof *out);
  out->st_mode = S_IFCHR | 0660;
  out->st_rdev = makedev(81, static_cast<unsigned>(camera));  // video4linux's major
  out->st_dev = makedev(0, 5);
  out->st_ino = 1000 + static_cast<ino_t>(camera);
  out->st_nlink = 1;
  out->st_uid = geteuid();
  out->st_gid = getegid();
  out->st_blksize = 4096;
}
}  // namespace

bool statPath(const char* path, struct stat* out) {
  if (path == nullptr || std::strncmp(path, "/dev/", 5) != 0) return false;
  State& s = state();
  std::lock_guard<std::mutex> g(s.lock);
  if (!attach(s)) return false;
  for (int c = 0; c < cv::kNumCameras; ++c)
    if (std::strncmp(path, s.block->camera[c].device, cv::kMaxDevicePath) == 0) {
      fillStat(c, out);
      return true;
    }
  return false;
}

bool isDevice(int fd) {
  State& s = state();
  std::lock_guard<std::mutex> g(s.lock);
  return s.fds.count(fd) != 0;
}

int ioctl(int fd, unsigned long request, void* arg) {
  State& s = state();
  std::unique_lock<std::mutex> held(s.lock);
  const auto it = s.fds.find(fd);
  if (it == s.fds.end()) return -2;
  // The kernel takes the request as 32 bits: a program that passes it
  // through an int (NaoTH's xioctl) hands glibc a sign-extended long.
  return handle(s, held, fd, s.camera[it->second], static_cast<uint32_t>(request), arg);
}

void* mmap(void* addr, size_t length, int prot, int flags, int fd, off_t offset) {
  State& s = state();
  std::lock_guard<std::mutex> g(s.lock);
  const auto it = s.fds.find(fd);
  Camera& c = s.camera[it->second];
  const size_t index = static_cast<size_t>(offset) / kOffsetStride;
  if (c.memory != V4L2_MEMORY_MMAP || offset < 0 || offset % kOffsetStride != 0 || index >= c.buffers.size() ||
      length == 0 || length > c.buffers[index].length) {
    errno = EINVAL;
    return MAP_FAILED;
  }
  return libc().mmap(addr, length, prot, flags, c.buffers[index].memfd, 0);
}

void stat(int fd, struct stat* out) {
  State& s = state();
  std::lock_guard<std::mutex> g(s.lock);
  fillStat(s.fds.count(fd) ? s.fds[fd] : 0, out);
}

void closing(int fd) {
  State& s = state();
  std::lock_guard<std::mutex> g(s.lock);
  const auto it = s.fds.find(fd);
  if (it == s.fds.end()) return;
  Camera& c = s.camera[it->second];
  s.fds.erase(it);
  open_count.fetch_sub(1, std::memory_order_release);
  if (--c.fds == 0) {  // its last fd: the device is released (streaming stops, buffers go)
    streamOff(s, c);
    freeBuffers(c);
  }
}

}  // namespace simswift::shim::v4l2
