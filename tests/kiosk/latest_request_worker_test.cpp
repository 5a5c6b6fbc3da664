// LatestRequestWorker (render/kiosk/latest_request_worker.h): the kiosk prepares lighting changes
// off the render thread, one at a time, and only the newest queued request is worth doing.
#include <gtest/gtest.h>

#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "kiosk/latest_request_worker.h"

using weft::LatestRequestWorker;

namespace {

// Work that runs only when the test lets it: each release() lets one call finish.
struct Gate {
  std::mutex m;
  std::condition_variable cv;
  int releases = 0;
  std::vector<int> started;
  int run(int x) {
    std::unique_lock<std::mutex> lock(m);
    started.push_back(x);
    cv.wait(lock, [&] { return releases > 0; });
    --releases;
    if (x < 0) throw std::runtime_error("bad request");
    return 10 * x;
  }
  void release() {
    {
      std::lock_guard<std::mutex> lock(m);
      ++releases;
    }
    cv.notify_all();
  }
};

template <class W>
int wait_for_result(W& w) {
  for (int i = 0; i < 5000; ++i) {
    if (auto r = w.take()) return *r;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ADD_FAILURE() << "no result within 5 s";
  return -1;
}

}  // namespace

TEST(LatestRequestWorker, RunsOneAtATimeAndSkipsStaleRequests) {
  Gate gate;
  LatestRequestWorker<int, int> w([&](const int& x) { return gate.run(x); });
  EXPECT_TRUE(w.idle());
  EXPECT_FALSE(w.take().has_value());
  w.request(1);
  w.request(2);  // queued behind 1 ...
  w.request(3);  // ... and replaced: 2 is stale
  EXPECT_FALSE(w.take().has_value());  // 1 is still running: take() does not block
  gate.release();
  EXPECT_EQ(wait_for_result(w), 10);
  EXPECT_FALSE(w.idle());  // 3 started when 1 was taken
  gate.release();
  EXPECT_EQ(wait_for_result(w), 30);
  EXPECT_TRUE(w.idle());
  std::lock_guard<std::mutex> lock(gate.m);
  EXPECT_EQ(gate.started, (std::vector<int>{1, 3}));
}

TEST(LatestRequestWorker, AFailedRequestIsReportedOnceAndTheNextStillRuns) {
  Gate gate;
  LatestRequestWorker<int, int> w([&](const int& x) { return gate.run(x); });
  w.request(-1);
  w.request(4);
  gate.release();
  bool thrown = false;
  for (int i = 0; i < 5000 && !thrown; ++i) {
    try {
      if (w.take()) break;
    } catch (const std::runtime_error&) {
      thrown = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_TRUE(thrown);
  gate.release();
  EXPECT_EQ(wait_for_result(w), 40);
  EXPECT_TRUE(w.idle());
}

TEST(LatestRequestWorker, DestructionWaitsForTheWorkInFlight) {
  Gate gate;
  bool finished = false;
  std::thread releaser;
  {
    LatestRequestWorker<int, int> w([&](const int& x) {
      const int r = gate.run(x);
      finished = true;
      return r;
    });
    w.request(5);
    releaser = std::thread([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      gate.release();
    });
  }  // the destructor returns only after the work has finished
  EXPECT_TRUE(finished);
  releaser.join();
}
