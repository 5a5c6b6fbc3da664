#pragma once
// One background computation at a time where only the newest request matters: the kiosk's
// lighting changes (a light probe's new fit, a turn of the environment knob) cost the CPU tens
// of ms (every shadowed object's per-(vertex, SG) visibility: SceneRenderer::prepare_lighting),
// which on the render thread would be dropped frames. request() starts the work, or queues it
// behind the one running (replacing any request queued before: it is stale); take() never
// blocks: it returns a finished result (and starts the queued request), or nothing yet.
#include <chrono>
#include <functional>
#include <future>
#include <optional>
#include <utility>

namespace weft {

template <class Request, class Result>
class LatestRequestWorker {
public:
  using Work = std::function<Result(const Request&)>;
  explicit LatestRequestWorker(Work work) : work_(std::move(work)) {}
  ~LatestRequestWorker() {
    if (running_.valid()) running_.wait();  // the work may use what the owner frees next
  }
  LatestRequestWorker(const LatestRequestWorker&) = delete;
  LatestRequestWorker& operator=(const LatestRequestWorker&) = delete;

  void request(Request r) {
    if (running_.valid())
      queued_ = std::move(r);
    else
      start(std::move(r));
  }

  // A finished result, if any. An exception from the work is rethrown here, once; the queued
  // request has started by then either way.
  std::optional<Result> take() {
    if (!running_.valid() || running_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
    std::future<Result> done = std::move(running_);
    if (queued_) {
      start(std::move(*queued_));
      queued_.reset();
    }
    return done.get();
  }

  bool idle() const { return !running_.valid() && !queued_; }

private:
  void start(Request r) {
    running_ = std::async(std::launch::async, [this, r = std::move(r)] { return work_(r); });
  }
  Work work_;
  std::future<Result> running_;
  std::optional<Request> queued_;
};

}  // namespace weft
