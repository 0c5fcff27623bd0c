/* A team's camera code as simswift meets it, written from the public Linux
 * V4L2 interface only (linux/videodev2.h, linux/uvcvideo.h; no simswift
 * header, like tests/lola_client): it opens the NAO's two cameras, asks
 * what a team's code asks, streams both with MMAP or with USERPTR buffers,
 * and reports on stdout, one line per fact:
 *
 *   camera_probe TOP BOTTOM FRAMES mmap|userptr [BODY-CLIENT ARGS...]
 *
 *   open top chardev=1 driver=uvcvideo caps=0x...
 *   control brightness=10 exposure_auto=1 uvc=...      (values set and read back)
 *   unknown_ioctl errno=25                               (a request no NAO driver knows)
 *   nonblock_empty errno=11                              (DQBUF before any frame)
 *   frame mem=mmap cam=top seq=0 t_us=... age_us=... bytes=... ball_x=... ball_y=... ball_n=...
 *   ...
 *   done frames=N digest=HEX                             (FNV-1a of every frame and time)
 *
 * FRAMES frames of each camera with MMAP or USERPTR buffers; top 640x480,
 * bottom 320x240. BODY-CLIENT (a LoLA or libagent client answering the
 * robot's body) is started once both cameras stream, and waited for. The
 * ball: findBall's centroid. CAMERA_PROBE_DUMP=PREFIX writes each camera's
 * last frame to PREFIX-t.yuyv / PREFIX-b.yuyv. Exit status 0 when
 * everything asked answered as a camera answers, else 1 with a line
 * "error ...". */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <linux/usb/video.h>
#include <linux/uvcvideo.h>
#include <linux/videodev2.h>
#include <poll.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define NBUF 3

struct camera {
  const char* name;
  int fd;
  unsigned width, height, sizeimage;
  void* start[NBUF];
  size_t length[NBUF];
  int taken;
};

static uint64_t digest = 1469598103934665603ull;
static void hash(const void* p, size_t n) {
  const unsigned char* b = p;
  for (size_t i = 0; i < n; ++i) digest = (digest ^ b[i]) * 1099511628211ull;
}

static void die(const char* what, const char* cam) {
  printf("error %s %s: %s\n", cam, what, strerror(errno));
  fflush(stdout);
  exit(1);
}

static int xioctl(int fd, unsigned long request, void* arg) {
  int r;
  do r = ioctl(fd, request, arg);
  while (r == -1 && errno == EINTR);
  return r;
}

static void setUp(struct camera* c, unsigned w, unsigned h) {
  struct stat st;
  /* NaoTH stats the path before it opens it. */
  if (stat(c->name, &st) != 0 || !S_ISCHR(st.st_mode)) die("stat (a character device)", c->name);
  c->fd = open(c->name, O_RDWR | O_NONBLOCK);
  if (c->fd < 0) die("open", c->name);
  if (fstat(c->fd, &st) != 0) die("fstat", c->name);
  struct v4l2_capability cap;
  memset(&cap, 0, sizeof cap);
  if (xioctl(c->fd, VIDIOC_QUERYCAP, &cap) != 0) die("QUERYCAP", c->name);
  printf("open %s chardev=%d driver=%s caps=0x%x\n", c->name, S_ISCHR(st.st_mode) ? 1 : 0, (char*)cap.driver,
         cap.device_caps);
  struct v4l2_format f;
  memset(&f, 0, sizeof f);
  f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  f.fmt.pix.width = w;
  f.fmt.pix.height = h;
  f.fmt.pix.pixelformat = V4L2_PIX_FMT_YUYV;
  f.fmt.pix.field = V4L2_FIELD_NONE;
  if (xioctl(c->fd, VIDIOC_S_FMT, &f) != 0) die("S_FMT", c->name);
  /* The request through an int, as NaoTH's xioctl passes it (sign-extended to a long). */
  const int request = (int)VIDIOC_G_FMT;
  memset(&f, 0, sizeof f);
  f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (xioctl(c->fd, request, &f) != 0) die("G_FMT (an int request)", c->name);
  c->width = f.fmt.pix.width;
  c->height = f.fmt.pix.height;
  c->sizeimage = f.fmt.pix.sizeimage;
  struct v4l2_streamparm p;
  memset(&p, 0, sizeof p);
  p.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  p.parm.capture.timeperframe.numerator = 1;
  p.parm.capture.timeperframe.denominator = 30;
  if (xioctl(c->fd, VIDIOC_S_PARM, &p) != 0) die("S_PARM", c->name);
  printf("format %s %ux%u sizeimage=%u fps=%u/%u\n", c->name, c->width, c->height, c->sizeimage,
         p.parm.capture.timeperframe.denominator, p.parm.capture.timeperframe.numerator);
}

static void start(struct camera* c, unsigned memory) {
  struct v4l2_requestbuffers rb;
  memset(&rb, 0, sizeof rb);
  rb.count = NBUF;
  rb.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  rb.memory = memory;
  if (xioctl(c->fd, VIDIOC_REQBUFS, &rb) != 0 || rb.count != NBUF) die("REQBUFS", c->name);
  for (unsigned i = 0; i < NBUF; ++i) {
    struct v4l2_buffer b;
    memset(&b, 0, sizeof b);
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = memory;
    b.index = i;
    if (memory == V4L2_MEMORY_MMAP) {
      if (xioctl(c->fd, VIDIOC_QUERYBUF, &b) != 0) die("QUERYBUF", c->name);
      c->length[i] = b.length;
      c->start[i] = mmap(NULL, b.length, PROT_READ | PROT_WRITE, MAP_SHARED, c->fd, b.m.offset);
      if (c->start[i] == MAP_FAILED) die("mmap", c->name);
    } else {
      c->length[i] = c->sizeimage;
      if (posix_memalign(&c->start[i], 4096, c->sizeimage) != 0) die("posix_memalign", c->name);
      b.m.userptr = (unsigned long)c->start[i];
      b.length = c->sizeimage;
    }
    if (xioctl(c->fd, VIDIOC_QBUF, &b) != 0) die("QBUF", c->name);
  }
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (xioctl(c->fd, VIDIOC_STREAMON, &type) != 0) die("STREAMON", c->name);
  c->taken = 0;
}

static void stop(struct camera* c, unsigned memory) {
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  if (xioctl(c->fd, VIDIOC_STREAMOFF, &type) != 0) die("STREAMOFF", c->name);
  for (unsigned i = 0; i < NBUF; ++i) {
    if (memory == V4L2_MEMORY_MMAP) munmap(c->start[i], c->length[i]);
    else free(c->start[i]);
  }
  struct v4l2_requestbuffers rb;
  memset(&rb, 0, sizeof rb);
  rb.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  rb.memory = memory;
  if (xioctl(c->fd, VIDIOC_REQBUFS, &rb) != 0) die("REQBUFS 0", c->name);
}

/* The ball (the SPL's white ball with black patches, on a green field):
 * its black patches are the image's only dark pixels (Y < 50); the ball is
 * every dark or white pixel (Y > 170) within 8 px of their bounding box.
 * Its centroid (px, pixel centres at i + 0.5) and count; -1, 0 if none. */
static void findBall(const unsigned char* yuyv, unsigned w, unsigned h, double* x, double* y, long* n) {
  long x0 = w, x1 = -1, y0 = h, y1 = -1;
  for (unsigned r = 0; r < h; ++r)
    for (unsigned col = 0; col < w; ++col)
      if (yuyv[((size_t)r * w + col) * 2] < 50) {
        if ((long)col < x0) x0 = col;
        if ((long)col > x1) x1 = col;
        if ((long)r < y0) y0 = r;
        if ((long)r > y1) y1 = r;
      }
  double sx = 0, sy = 0;
  *n = 0;
  for (long r = y0 - 8; x1 >= 0 && r <= y1 + 8; ++r)
    for (long col = x0 - 8; col <= x1 + 8; ++col) {
      if (r < 0 || col < 0 || r >= (long)h || col >= (long)w) continue;
      const int luma = yuyv[((size_t)r * w + col) * 2];
      if (luma < 50 || luma > 170) {
        sx += col + 0.5;
        sy += r + 0.5;
        ++*n;
      }
    }
  *x = *n ? sx / *n : -1;
  *y = *n ? sy / *n : -1;
}

static void take(struct camera* c, unsigned memory, const char* mem_name) {
  struct v4l2_buffer b;
  for (;;) {
    memset(&b, 0, sizeof b);
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = memory;
    if (xioctl(c->fd, VIDIOC_DQBUF, &b) != 0) {
      if (errno == EAGAIN) return; /* drained, as B-Human drains */
      die("DQBUF", c->name);
    }
    const unsigned char* data = c->start[b.index];
    if (memory == V4L2_MEMORY_USERPTR && (void*)b.m.userptr != c->start[b.index]) {
      errno = EINVAL;
      die("DQBUF userptr", c->name);
    }
    const long long t_us = (long long)b.timestamp.tv_sec * 1000000 + b.timestamp.tv_usec;
    /* The buffer's age on the program's own CLOCK_MONOTONIC (the base a UVC
       driver stamps TIMESTAMP_MONOTONIC buffers in). */
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    const long long age_us = (long long)now.tv_sec * 1000000 + now.tv_nsec / 1000 - t_us;
    double x, y;
    long n;
    findBall(data, c->width, c->height, &x, &y, &n);
    hash(data, b.bytesused);
    hash(&t_us, sizeof t_us);
    printf("frame mem=%s cam=%s seq=%u t_us=%lld age_us=%lld bytes=%u mono=%d ball_x=%.2f ball_y=%.2f ball_n=%ld\n",
           mem_name, c->name, b.sequence, t_us, age_us, b.bytesused,
           (b.flags & V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC) ? 1 : 0, x, y, n);
    const char* dump = getenv("CAMERA_PROBE_DUMP"); /* the last frame's bytes, to look at */
    if (dump) {
      char path[512];
      snprintf(path, sizeof path, "%s-%c.yuyv", dump, c->width == 640 ? 't' : 'b');
      FILE* out = fopen(path, "wb");
      if (out) fwrite(data, 1, b.bytesused, out), fclose(out);
    }
    ++c->taken;
    if (xioctl(c->fd, VIDIOC_QBUF, &b) != 0) die("QBUF again", c->name);
  }
}

static void stream(struct camera* cams, unsigned memory, const char* mem_name, int frames) {
  /* Nothing dequeued before a frame came: EAGAIN (non-blocking). */
  if (memory == V4L2_MEMORY_MMAP) {
    struct v4l2_buffer b;
    memset(&b, 0, sizeof b);
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = memory;
    const int r = xioctl(cams[0].fd, VIDIOC_DQBUF, &b);
    printf("nonblock_empty errno=%d\n", r == 0 ? 0 : errno);
  }
  while (cams[0].taken < frames || cams[1].taken < frames) {
    struct pollfd p[2] = {{cams[0].fd, POLLIN | POLLPRI, 0}, {cams[1].fd, POLLIN | POLLPRI, 0}};
    const int r = poll(p, 2, 20000);
    if (r == 0) {
      errno = ETIMEDOUT;
      die("poll", "both");
    }
    if (r < 0 && errno != EINTR) die("poll", "both");
    for (int i = 0; i < 2; ++i)
      if (p[i].revents & POLLIN) take(&cams[i], memory, mem_name);
  }
  for (int i = 0; i < 2; ++i) stop(&cams[i], memory);
}

static void controls(struct camera* c) {
  struct v4l2_queryctrl q;
  memset(&q, 0, sizeof q);
  q.id = V4L2_CID_BRIGHTNESS;
  if (xioctl(c->fd, VIDIOC_QUERYCTRL, &q) != 0) die("QUERYCTRL", c->name);
  struct v4l2_control ctl = {V4L2_CID_BRIGHTNESS, 10};
  if (xioctl(c->fd, VIDIOC_S_CTRL, &ctl) != 0) die("S_CTRL", c->name);
  ctl.value = 0;
  if (xioctl(c->fd, VIDIOC_G_CTRL, &ctl) != 0) die("G_CTRL", c->name);
  struct v4l2_ext_control e = {.id = V4L2_CID_EXPOSURE_AUTO, .value = V4L2_EXPOSURE_MANUAL};
  struct v4l2_ext_controls x;
  memset(&x, 0, sizeof x);
  x.which = V4L2_CTRL_WHICH_CUR_VAL;
  x.count = 1;
  x.controls = &e;
  if (xioctl(c->fd, VIDIOC_S_EXT_CTRLS, &x) != 0) die("S_EXT_CTRLS", c->name);
  e.value = -1;
  if (xioctl(c->fd, VIDIOC_G_EXT_CTRLS, &x) != 0) die("G_EXT_CTRLS", c->name);
  /* The extension unit's register access (unit 3, selector 14): write a register, read it back. */
  unsigned char w[5] = {1, 0x50, 0x0a, 0x12, 0x34}, rd[5] = {0, 0x50, 0x0a, 0, 0};
  struct uvc_xu_control_query xu = {3, 14, UVC_SET_CUR, 5, w};
  if (xioctl(c->fd, UVCIOC_CTRL_QUERY, &xu) != 0) die("UVC SET_CUR", c->name);
  xu.data = rd;
  if (xioctl(c->fd, UVCIOC_CTRL_QUERY, &xu) != 0) die("UVC SET_CUR read", c->name);
  xu.query = UVC_GET_CUR;
  if (xioctl(c->fd, UVCIOC_CTRL_QUERY, &xu) != 0) die("UVC GET_CUR", c->name);
  printf("control %s brightness_max=%d brightness=%d exposure_auto=%d register=0x%02x%02x\n", c->name, q.maximum,
         ctl.value, e.value, rd[3], rd[4]);
  /* A request no camera driver knows (a DVB frontend's): an errno, never a crash. */
  errno = 0;
  const int r = ioctl(c->fd, _IO('o', 66), 0);
  printf("unknown_ioctl result=%d errno=%d\n", r, errno);
}

int main(int argc, char** argv) {
  if (argc < 5 || (strcmp(argv[4], "mmap") != 0 && strcmp(argv[4], "userptr") != 0)) {
    fprintf(stderr, "usage: camera_probe TOP BOTTOM FRAMES mmap|userptr [BODY-CLIENT ARGS...]\n");
    return 2;
  }
  setvbuf(stdout, NULL, _IOLBF, 0);
  struct camera cams[2] = {{.name = argv[1]}, {.name = argv[2]}};
  const int frames = atoi(argv[3]);
  const unsigned memory = strcmp(argv[4], "mmap") == 0 ? V4L2_MEMORY_MMAP : V4L2_MEMORY_USERPTR;
  setUp(&cams[0], 640, 480);
  setUp(&cams[1], 320, 240);
  controls(&cams[0]);
  for (int i = 0; i < 2; ++i) start(&cams[i], memory);
  /* Streaming before the robot's body is answered: the first frame is the
   * run's first, whatever the machine's speed. */
  pid_t body = -1;
  if (argc > 5) {
    body = fork();
    if (body == 0) {
      execv(argv[5], argv + 5);
      _exit(127);
    }
  }
  stream(cams, memory, argv[4], frames);
  close(cams[0].fd);
  close(cams[1].fd);
  printf("done frames=%d digest=%016llx\n", frames, (unsigned long long)digest);
  if (body > 0) waitpid(body, NULL, 0); /* the body client answers until the run ends */
  return 0;
}
