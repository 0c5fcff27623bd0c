/* A team program's clock and timed waits, as a V6 or V5 team would write
 * them, from public Linux facts only (clock_gettime(2), nanosleep(2),
 * pthread_cond_timedwait(3), sem_timedwait(3), poll(2), select(2),
 * epoll_wait(2), timerfd_create(2), proc(5)), LoLA's (a Unix socket,
 * 896-byte msgpack packets every 12 ms; facts.md section 9) and libagent's
 * (the public rUNSWift 2017 release's 3284-byte block in POSIX shared
 * memory and its semaphore, a cycle every 10 ms; docs/libagent.md): no
 * simswift header. It holds nothing of simswift's; under simswift its
 * clocks should read the run's simulated time.
 *
 *   clock-probe SOCKET CYCLES KINDS
 *
 * SOCKET is LoLA's socket (a V6), or a libagent block's name,
 * /libagent-memory<N> (a V5: its semaphore is /libagent-semaphore<N>).
 * The main thread answers every LoLA packet or libagent cycle (stiffness 0,
 * limp) and reads every clock after each; it checks each advanced exactly
 * one cycle (12 ms LoLA, 10 ms libagent) since the last. A second thread waits in each of KINDS
 * (comma-separated, below) for 30 ms (sleep: 1 s) from a packet's time; the
 * main thread answers no packet while that thread is between reading its
 * start time and blocking (proc(5)'s task state), and none after the wait's
 * end time until the thread has woken, so what the thread reads is exact:
 * the wait must end at the first cycle at or after the time asked for.
 * The clocks include MONOTONIC read with the raw syscall (syscall(2)), as a
 * runtime that bypasses libc reads it; the waits syscall_nanosleep.
 * Prints "clock ... steps=N bad=M", "wait KIND start=... end=... want=..."
 * and "digest HEX" (FNV-1a of every reading); exit 0 when everything
 * matched, 1 on a mismatch, 2 on bad use. SOCKET "-" is /tmp/robocup. */
#define _GNU_SOURCE
#include <errno.h>
#include <poll.h>
#include <pthread.h>
#include <semaphore.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/epoll.h>
#include <sys/select.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <sys/time.h>
#include <sys/timerfd.h>
#include <sys/un.h>
#include <time.h>
#include <unistd.h>

#include <fcntl.h>
#include <sys/mman.h>

static int64_t cycle_ns = 12000000LL; /* LoLA: one packet every 12 ms; libagent: 10 ms */
#define WAIT_NS 30000000LL  /* 2.5 LoLA cycles (3 libagent cycles): the wait ends on the third */
#define PACKET 896

/* The rUNSWift 2017 libagent block's offsets (x86-64, its AgentData):
 * the four indices, the command slots (JointValues, 400 bytes each),
 * stiffen[3] (an enum each) and `standing`. */
enum { LA_SENSORS_READ = 0, LA_SENSORS_LATEST = 1, LA_ACTUATORS_LATEST = 2, LA_ACTUATORS_READ = 3,
       LA_JOINTS = 1892, LA_JOINT_VALUES = 400, LA_STIFFEN = 3164, LA_STANDING = 3281, LA_SIZE = 3284 };

static uint64_t digest = 1469598103934665603ULL;
static void mix(int64_t v) {
  for (int i = 0; i < 8; ++i) {
    digest ^= (uint64_t)((v >> (8 * i)) & 0xff);
    digest *= 1099511628211ULL;
  }
}
static int64_t ns(struct timespec t) { return (int64_t)t.tv_sec * 1000000000LL + t.tv_nsec; }
static struct timespec ts(int64_t v) {
  struct timespec t = {(time_t)(v / 1000000000LL), (long)(v % 1000000000LL)};
  return t;
}
static int64_t now(clockid_t c) {
  struct timespec t;
  clock_gettime(c, &t);
  return ns(t);
}

/* The waiting thread and the main thread's hand-over. */
enum { IDLE, GO, CALLING, DONE };
static pthread_mutex_t m = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t changed = PTHREAD_COND_INITIALIZER;
static int state = IDLE;
static pid_t waiter_tid;
static char kind[64];
static int64_t w_start, w_end, w_want; /* on the wait's own clock */
static int w_ret;
static int failures;

static void waitFor(int s) {
  pthread_mutex_lock(&m);
  while (state != s) pthread_cond_wait(&changed, &m);
  pthread_mutex_unlock(&m);
}
static void setState(int s) {
  pthread_mutex_lock(&m);
  state = s;
  pthread_cond_broadcast(&changed);
  pthread_mutex_unlock(&m);
}

/* proc(5): /proc/self/task/TID/stat's third field is the task's state. */
static char taskState(pid_t tid) {
  char path[64], buf[512];
  snprintf(path, sizeof path, "/proc/self/task/%d/stat", (int)tid);
  FILE* f = fopen(path, "r");
  if (!f) return '?';
  size_t n = fread(buf, 1, sizeof buf - 1, f);
  fclose(f);
  buf[n] = 0;
  char* p = strrchr(buf, ')');
  return p && p[1] == ' ' ? p[2] : '?';
}

static int64_t roundUpCycle(int64_t start, int64_t wait) {
  return start + (wait + cycle_ns - 1) / cycle_ns * cycle_ns;
}

/* One wait of `kind`: sets w_start (before), w_end (after) and w_want. */
static void doWait(const char* k) {
  clockid_t c = CLOCK_MONOTONIC;
  if (!strcmp(k, "clock_nanosleep_abs_realtime") || !strcmp(k, "cond_timedwait") || !strcmp(k, "sem_timedwait"))
    c = CLOCK_REALTIME;
  int64_t wait = !strcmp(k, "sleep") ? 1000000000LL : WAIT_NS;
  pthread_mutex_lock(&m);
  w_start = now(c);
  w_want = roundUpCycle(w_start, wait);
  state = CALLING;
  pthread_cond_broadcast(&changed);
  pthread_mutex_unlock(&m);
  int r = 0;
  int64_t deadline = w_start + wait;
  struct timespec rel = ts(wait), abs = ts(deadline);
  if (!strcmp(k, "nanosleep")) r = nanosleep(&rel, NULL);
  else if (!strcmp(k, "clock_nanosleep")) r = clock_nanosleep(CLOCK_MONOTONIC, 0, &rel, NULL);
  else if (!strcmp(k, "clock_nanosleep_abs")) r = clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &abs, NULL);
  else if (!strcmp(k, "clock_nanosleep_abs_realtime")) r = clock_nanosleep(CLOCK_REALTIME, TIMER_ABSTIME, &abs, NULL);
  else if (!strcmp(k, "syscall_nanosleep")) r = (int)syscall(SYS_nanosleep, &rel, NULL);
  else if (!strcmp(k, "usleep")) r = usleep((useconds_t)(wait / 1000));
  else if (!strcmp(k, "sleep")) r = (int)sleep(1);
  else if (!strcmp(k, "cond_timedwait") || !strcmp(k, "cond_clockwait") || !strcmp(k, "cond_monotonic")) {
    pthread_mutex_t cm = PTHREAD_MUTEX_INITIALIZER;
    pthread_cond_t cv;
    pthread_condattr_t a;
    pthread_condattr_init(&a);
    if (!strcmp(k, "cond_monotonic")) pthread_condattr_setclock(&a, CLOCK_MONOTONIC);
    pthread_cond_init(&cv, &a);
    pthread_mutex_lock(&cm);
    if (!strcmp(k, "cond_clockwait")) r = pthread_cond_clockwait(&cv, &cm, CLOCK_MONOTONIC, &abs);
    else r = pthread_cond_timedwait(&cv, &cm, &abs);
    pthread_mutex_unlock(&cm);
    r = r == ETIMEDOUT ? 0 : r ? r : -1; /* only a timeout may end it */
  } else if (!strcmp(k, "sem_timedwait") || !strcmp(k, "sem_clockwait")) {
    sem_t s;
    sem_init(&s, 0, 0);
    r = !strcmp(k, "sem_clockwait") ? sem_clockwait(&s, CLOCK_MONOTONIC, &abs) : sem_timedwait(&s, &abs);
    r = r == -1 && errno == ETIMEDOUT ? 0 : -1;
  } else {
    int p[2];
    if (pipe(p) != 0) exit(2); /* never written: only the timeout ends the wait */
    struct pollfd pf = {p[0], POLLIN, 0};
    fd_set rd;
    FD_ZERO(&rd);
    FD_SET(p[0], &rd);
    struct timeval tv = {0, (suseconds_t)(wait / 1000)};
    int ep = epoll_create1(0);
    struct epoll_event ev = {EPOLLIN, {0}}, out;
    epoll_ctl(ep, EPOLL_CTL_ADD, p[0], &ev);
    if (!strcmp(k, "poll")) r = poll(&pf, 1, (int)(wait / 1000000));
    else if (!strcmp(k, "poll_nofds")) r = poll(NULL, 0, (int)(wait / 1000000));
    else if (!strcmp(k, "ppoll")) r = ppoll(&pf, 1, &rel, NULL);
    else if (!strcmp(k, "select")) r = select(p[0] + 1, &rd, NULL, NULL, &tv);
    else if (!strcmp(k, "select_nofds")) r = select(0, NULL, NULL, NULL, &tv);
    else if (!strcmp(k, "pselect")) r = pselect(p[0] + 1, &rd, NULL, NULL, &rel, NULL);
    else if (!strcmp(k, "epoll_wait")) r = epoll_wait(ep, &out, 1, (int)(wait / 1000000));
    else if (!strcmp(k, "epoll_pwait")) r = epoll_pwait(ep, &out, 1, (int)(wait / 1000000), NULL);
    else if (!strcmp(k, "timerfd")) {
      int t = timerfd_create(CLOCK_MONOTONIC, 0);
      struct itimerspec it = {{0, 0}, rel};
      timerfd_settime(t, 0, &it, NULL);
      uint64_t n = 0;
      r = read(t, &n, sizeof n) == sizeof n && n == 1 ? 0 : -1;
      close(t);
    } else {
      fprintf(stderr, "clock-probe: unknown kind %s\n", k);
      exit(2);
    }
    close(p[0]), close(p[1]), close(ep);
  }
  w_ret = r;
  w_end = now(c);
}

static char kinds[2048];
static void* waiter(void* arg) {
  (void)arg;
  waiter_tid = (pid_t)syscall(SYS_gettid);
  for (char* save = NULL, *k = strtok_r(kinds, ",", &save); k; k = strtok_r(NULL, ",", &save)) {
    waitFor(GO);
    snprintf(kind, sizeof kind, "%s", k);
    doWait(k);
    setState(DONE);
  }
  return NULL;
}

static int readAll(int fd, unsigned char* d, size_t n) {
  while (n > 0) {
    ssize_t r = read(fd, d, n);
    if (r <= 0) return 0;
    d += r, n -= (size_t)r;
  }
  return 1;
}

/* A runtime's start-up (a sanitizer's, ld.so's .preinit_array: before any
 * library's constructor) reading the clock with the raw syscall. Printed by
 * main as "preinit raw clock_gettime rc=R". */
static long preinit_rc = -1;
static void readClockAtPreinit(int argc, char** argv, char** envp) {
  (void)argc, (void)argv, (void)envp;
  struct timespec t;
  preinit_rc = syscall(SYS_clock_gettime, CLOCK_MONOTONIC, &t);
}
__attribute__((section(".preinit_array"), used)) static void (*const preinit)(int, char**, char**) = readClockAtPreinit;

int main(int argc, char** argv) {
  printf("preinit raw clock_gettime rc=%ld\n", preinit_rc);
  if (argc != 4) {
    fprintf(stderr, "usage: clock-probe SOCKET CYCLES KINDS\n");
    return 2;
  }
  const int cycles = atoi(argv[2]);
  snprintf(kinds, sizeof kinds, "%s", argv[3]);
  int nkinds = kinds[0] ? 1 : 0;
  for (const char* p = kinds; *p; ++p) nkinds += *p == ',';
  /* A V5: libagent's block and semaphore (opened with O_CREAT, as the 2017
   * release's clients do: either side may come first). */
  volatile unsigned char* block = NULL;
  sem_t* cycle_sem = NULL;
  int fd = -1;
  if (!strncmp(argv[1], "/libagent-memory", 16)) {
    cycle_ns = 10000000LL;
    char sem_name[128];
    snprintf(sem_name, sizeof sem_name, "/libagent-semaphore%s", argv[1] + 16);
    int m_fd = shm_open(argv[1], O_CREAT | O_RDWR, 0600);
    void* p = m_fd < 0 ? MAP_FAILED : mmap(NULL, LA_SIZE, PROT_READ | PROT_WRITE, MAP_SHARED, m_fd, 0);
    if (m_fd >= 0) close(m_fd);
    cycle_sem = sem_open(sem_name, O_CREAT, 0600, 0);
    if (p == MAP_FAILED || cycle_sem == SEM_FAILED) {
      perror("clock-probe: libagent");
      return 1;
    }
    block = (volatile unsigned char*)p;
  } else {
    struct sockaddr_un a = {AF_UNIX, {0}};
    snprintf(a.sun_path, sizeof a.sun_path, "%s", strcmp(argv[1], "-") ? argv[1] : "/tmp/robocup");
    fd = socket(AF_UNIX, SOCK_STREAM, 0);
    if (connect(fd, (struct sockaddr*)&a, sizeof a) != 0) {
      perror("clock-probe: connect");
      return 1;
    }
  }
  pthread_t th;
  pthread_create(&th, NULL, waiter, NULL);
  /* LoLA's answer: {"Stiffness": [25 x 0.0f]} in msgpack. */
  unsigned char answer[1 + 10 + 3 + 25 * 5], *q = answer;
  *q++ = 0x81, *q++ = 0xa9, memcpy(q, "Stiffness", 9), q += 9, *q++ = 0xdc, *q++ = 0, *q++ = 25;
  for (int i = 0; i < 25; ++i) *q++ = 0xca, *q++ = 0, *q++ = 0, *q++ = 0, *q++ = 0;
  static const struct { clockid_t id; const char* name; } clocks[] = {
      {CLOCK_MONOTONIC, "MONOTONIC"}, {CLOCK_REALTIME, "REALTIME"}, {CLOCK_BOOTTIME, "BOOTTIME"},
      {CLOCK_MONOTONIC_RAW, "MONOTONIC_RAW"}, {CLOCK_MONOTONIC_COARSE, "MONOTONIC_COARSE"},
      {CLOCK_REALTIME_COARSE, "REALTIME_COARSE"}};
  enum { NC = sizeof clocks / sizeof clocks[0] };
  int64_t last[NC + 2] = {0}, bad[NC + 2] = {0};
  int done = 0, started = 0;
  unsigned char packet[PACKET];
  for (int cycle = 0; cycle < cycles; ++cycle) {
    if (block) {
      while (sem_wait(cycle_sem) != 0)
        if (errno != EINTR) {
          perror("clock-probe: sem_wait");
          return 1;
        }
      block[LA_SENSORS_READ] = block[LA_SENSORS_LATEST];
    } else if (!readAll(fd, packet, PACKET)) {
      fprintf(stderr, "clock-probe: the socket closed at packet %d\n", cycle);
      return 1;
    }
    for (int c = 0; c <= NC + 1; ++c) {
      int64_t v;
      if (c < NC) v = now(clocks[c].id);
      else if (c == NC + 1) { /* the raw syscall, as a runtime that bypasses libc makes it */
        struct timespec t;
        syscall(SYS_clock_gettime, CLOCK_MONOTONIC, &t);
        v = ns(t);
      } else {
        struct timeval tv;
        gettimeofday(&tv, NULL);
        v = ((int64_t)tv.tv_sec * 1000000 + tv.tv_usec) * 1000; /* us -> ns */
      }
      mix(v);
      if (cycle > 0 && v - last[c] != cycle_ns) ++bad[c];
      last[c] = v;
    }
    mix((int64_t)time(NULL));
    /* The wait in progress: once its time has come, the thread must wake
     * (its end is read before this packet is answered). */
    pthread_mutex_lock(&m);
    int s = state;
    int64_t want = w_want;
    pthread_mutex_unlock(&m);
    if (s == CALLING) {
      clockid_t c = strstr(kind, "realtime") || !strcmp(kind, "cond_timedwait") || !strcmp(kind, "sem_timedwait")
                        ? CLOCK_REALTIME : CLOCK_MONOTONIC;
      if (now(c) >= want) waitFor(DONE), s = DONE;
    }
    if (s == DONE) {
      const int ok = w_ret == 0 && w_end == w_want;
      printf("wait %s start=%lld end=%lld want=%lld ret=%d %s\n", kind, (long long)w_start, (long long)w_end,
             (long long)w_want, w_ret, ok ? "ok" : "BAD");
      mix(w_end - w_start);
      if (!ok) ++failures;
      ++done;
      setState(IDLE);
      s = IDLE;
    }
    /* From the second packet: the first is answered before any wait (until
     * a program's first answer its time has not started: waits end at once). */
    if (s == IDLE && started < nkinds && cycle > 0) {
      ++started;
      setState(GO);
      waitFor(CALLING);
      while (taskState(waiter_tid) != 'S') sched_yield(); /* blocked in its wait */
    }
    if (block) { /* the Effector's slot loop: a zero command (stiffness 0) */
      int i = 0;
      while (i != block[LA_ACTUATORS_LATEST] && i != block[LA_ACTUATORS_READ]) ++i;
      for (int b = 0; b < LA_JOINT_VALUES; ++b) block[LA_JOINTS + i * LA_JOINT_VALUES + b] = 0;
      for (int b = 0; b < 4; ++b) block[LA_STIFFEN + i * 4 + b] = 0;
      if (block[LA_STANDING]) block[LA_STANDING] = 0;
      __atomic_thread_fence(__ATOMIC_SEQ_CST);
      block[LA_ACTUATORS_LATEST] = (unsigned char)i;
    } else if (write(fd, answer, sizeof answer) != (ssize_t)sizeof answer) {
      fprintf(stderr, "clock-probe: write failed at packet %d\n", cycle);
      return 1;
    }
  }
  for (int c = 0; c <= NC + 1; ++c) {
    printf("clock %s steps=%d bad=%lld\n", c < NC ? clocks[c].name : c == NC ? "gettimeofday" : "syscall_MONOTONIC",
           cycles - 1, (long long)bad[c]);
    if (bad[c]) ++failures;
  }
  if (done != nkinds) {
    printf("waits done %d of %d\n", done, nkinds);
    ++failures;
  }
  printf("digest %016llx\n", (unsigned long long)digest);
  fflush(stdout);
  return failures ? 1 : 0;
}
