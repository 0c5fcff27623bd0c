// The shim's one extra thread in the program: it sleeps on the clock page's
// generation word (woken once per tick, no polling) and, when a registered
// deadline is reached, wakes the wait that registered it: a condition
// variable (broadcast, under its mutex so no wakeup is lost), a semaphore's
// futex word, a thread's eventfd (poll, select, epoll), a timerfd's
// expirations (TimerFd.cpp). Started at the first wait that needs it.
#pragma once

#include <pthread.h>

#include <cstdint>

namespace simswift::shim {

enum class Alarm { CondBroadcast, FutexWake, EventfdWrite, Timer };

struct AlarmSpec {
  Alarm kind;
  int64_t deadline_ns;  // run time
  pthread_cond_t* cond = nullptr;
  pthread_mutex_t* mutex = nullptr;
  uint32_t* word = nullptr;  // FutexWake
  int futex_private = 0;     // FutexWake: FUTEX_PRIVATE_FLAG or 0
  int fd = -1;               // EventfdWrite, Timer: the eventfd written
  int64_t period_ns = 0;     // Timer: 0 = one shot
};

// A handle (>= 0), or -1 when the table is full (the caller says so).
int addAlarm(const AlarmSpec& spec);
// Removes it; waits while the timekeeper is firing it (so what it points at
// may go after this returns). True if it had fired (a one-shot alarm).
bool removeAlarm(int handle);
// A timer's expirations counted so far and its next deadline (Timer only).
bool alarmState(int handle, int64_t* next_deadline_ns);

}  // namespace simswift::shim
