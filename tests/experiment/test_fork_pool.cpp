// ForkPool's stop: a SIGTERM to the batch alone reaches its workers at once,
// whenever it arrives -- also just after the pool checked for a stop and
// before it waits (issue 45: such a signal waited until a worker ended).
#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "app/experiment/ForkPool.hpp"

namespace {

namespace fs = std::filesystem;
using simswift::experiment::ForkJob;
using simswift::experiment::runForked;

// Workers that would sleep 20 s; the parent sends itself SIGTERM the first
// time the pool is about to wait (ForkJob::waiting), after the stop check.
class SleepyJob : public ForkJob {
 public:
  explicit SleepyJob(std::string dir) : dir_(std::move(dir)) {}
  std::string logFile(int t) const override { return dir_ + "/" + std::to_string(t) + ".log"; }
  void run(int) const override { sleep(20); }
  bool done(int) const override { return false; }
  void finished(int, double) override { ++finished_; }
  void failed(int, const std::string&) override { ++failed_; }
  void waiting() override {
    if (sent_) return;
    sent_ = true;
    kill(getpid(), SIGTERM);
  }
  int finished_ = 0, failed_ = 0;

 private:
  std::string dir_;
  bool sent_ = false;
};

}  // namespace

TEST(ForkPool, ASigtermJustBeforeTheWaitReachesTheWorkersAtOnce) {
  const fs::path dir = fs::temp_directory_path() / ("simswift_fork_pool_" + std::to_string(getpid()));
  fs::create_directories(dir);
  SleepyJob job(dir.string());
  const auto t0 = std::chrono::steady_clock::now();
  const auto run = runForked(job, {0, 1, 2}, 2, false);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(run.interrupted);
  // The workers end on the passed-on SIGTERM: well under their 20 s sleep
  // (5 s allows for a loaded machine; before the fix this took the 20 s).
  EXPECT_LT(s, 5.0) << "the stop waited for a worker to end";
  EXPECT_EQ(run.ran, 0);
  EXPECT_EQ(run.failed, 0);  // interrupted, not failed
  EXPECT_EQ(job.failed_, 0);
  // The third trial never started, and the pool left no log behind.
  EXPECT_FALSE(fs::exists(dir / "2.log"));
  EXPECT_FALSE(fs::exists(dir / "0.log"));
  fs::remove_all(dir);
}
