#pragma once
// The live light probe: camera frames -> 10 SGs, off the render thread.
//
// One update: capture a bracket of exposures (`stops` frames, `stop_spacing` stops apart) ->
// merge to linear HDR radiance (hdr_merge.h) -> unwrap the mirror ball to an equirect map in the
// world frame (mirror_ball_unwrap.h) -> temporal smoothing of that map -> fit K SGs warm-started
// from the previous fit (render/lighting/sg_fit.h) -> publish.
//
// Temporal smoothing works on the unwrapped map (linear in radiance, so it never mixes lobes):
// an exponential moving average with weight `smoothing` for the new map, except that when the
// new map's irradiance at the six axis normals differs from the smoothed one by more than
// `snap_threshold` (relative to the mean), the scene has changed (a lamp switched on) and the
// average restarts from the new map. A static room: sensor noise averages out; a lamp: shows on
// the next update.
//
// Failures (camera absent, busy, unplugged mid-capture, timeouts, black or saturated frames)
// keep the last good SGs (the stored lighting until the first fit), log ONE line when the
// probe enters a failure (and one when it recovers), and retry with exponential backoff
// (`retry_initial_s` doubling up to `retry_max_s`), reopening the camera.
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "camera/camera_response.h"
#include "camera/light_probe_source.h"
#include "camera/mirror_ball.h"
#include "probe/sg_triple_buffer.h"
#include "journal/journal_log.h"
#include "lighting/env_map.h"
#include "lighting/sg_fit.h"

namespace weft {

struct LightProbeConfig {
  MirrorBall ball{200.0, 200.0, 190.0};
  CameraCalibration calibration;
  int stops = 4;               // frames per bracket (4 × 3 stops: a sun and a dim room in one bracket)
  double stop_spacing = 3.0;   // stops (factors of 2 in exposure) between them
  ProbeExposure shortest{1.0 / 1000.0, 1.0};  // start of the bracket; auto exposure moves it
  bool auto_exposure = true;   // keep the brightest ball pixel just below clipping
  double min_exposure_s = 1e-5, max_exposure_s = 0.25;
  int map_width = 128;         // unwrapped map (height = width / 2)
  SgFitOptions fit{10, 64, 1.0, 1000.0, 8};  // warm-started: few iterations are enough
  double smoothing = 0.5;      // EMA weight of the newest map (90 % of a small change in 4 updates)
  double snap_threshold = 0.1; // relative irradiance change that restarts the average
  double retry_initial_s = 0.5, retry_max_s = 30.0;
  double min_update_interval_s = 0.0;  // worker pacing (0: as fast as the camera delivers)
};

struct ProbeTimings {
  double capture_ms = 0, merge_ms = 0, unwrap_ms = 0, smooth_ms = 0, fit_ms = 0, total_ms = 0;  // wall clock
  double fit_cpu_ms = 0;  // the fit's CPU time on the worker thread (what a busy machine does not inflate)
};

enum class ProbeStepResult { updated, failed, waiting };  // waiting: in backoff, nothing tried

using Clock = std::chrono::steady_clock;

// The synchronous core: one update per step(). Used by the worker thread, and directly by
// tests and `weft probe` (with an injected clock, so the backoff is checkable without sleeping).
class LightProbeUpdater {
public:
  using Log = LogSink;  // journal_log.h
  using Now = std::function<Clock::time_point()>;

  LightProbeUpdater(LightProbeSource& source, LightProbeConfig config, SgLighting stored, Log log = {}, Now now = {});

  ProbeStepResult step();

  const SgLighting& sgs() const { return sgs_; }        // last good (or stored) lighting
  bool live() const { return fitted_ && !failing_; }    // the last attempt succeeded
  bool has_fit() const { return fitted_; }
  const EnvMap& smoothed_map() const { return smoothed_; }
  const ProbeTimings& timings() const { return timings_; }
  const SgFitStats& fit_stats() const { return fit_stats_; }
  const ProbeExposure& shortest_exposure() const { return shortest_; }
  std::optional<ProbeFailure> failure() const { return failing_ ? std::optional(failure_kind_) : std::nullopt; }
  Clock::time_point retry_at() const { return retry_at_; }
  double backoff_s() const { return backoff_s_; }
  bool snapped() const { return snapped_; }  // the last update restarted the average

private:
  void fail(const ProbeError& error);
  void adjust_exposure(double factor);

  LightProbeSource& source_;
  LightProbeConfig config_;
  SgLighting sgs_;
  Log log_;
  Now now_;
  bool open_ = false, fitted_ = false, failing_ = false, snapped_ = false;
  ProbeFailure failure_kind_ = ProbeFailure::absent;
  Clock::time_point retry_at_{};
  double backoff_s_ = 0;
  EnvMap smoothed_;
  ProbeTimings timings_;
  SgFitStats fit_stats_;
  ProbeExposure shortest_;
};

// The worker thread around an updater, and the renderer's side of the hand-off.
class LightProbe {
public:
  LightProbe(std::unique_ptr<LightProbeSource> source, LightProbeConfig config, SgLighting stored,
             LightProbeUpdater::Log log = {});
  ~LightProbe();  // stops and joins the worker
  LightProbe(const LightProbe&) = delete;
  LightProbe& operator=(const LightProbe&) = delete;

  void start();
  void stop();

  // Render thread, once per frame: never blocks. True when newer SGs arrived since the last call.
  bool acquire() { return buffer_.acquire(); }
  const SgLighting& lighting() const { return buffer_.front(); }
  uint64_t updates() const { return updates_.load(); }

  LightProbeSource& source() { return *source_; }

private:
  void run();

  std::unique_ptr<LightProbeSource> source_;
  LightProbeUpdater updater_;
  LightProbeConfig config_;
  SgTripleBuffer buffer_;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::atomic<uint64_t> updates_{0};
};

// The default log line sink: "weft probe: ..." on stderr.
void log_probe_line(LogPriority priority, const std::string& line);

}  // namespace weft
