#include "probe/light_probe_pipeline.h"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "camera/hdr_merge.h"
#include "probe/mirror_ball_unwrap.h"

namespace weft {

const char* to_string(ProbeFailure failure) {
  switch (failure) {
    case ProbeFailure::absent: return "camera absent";
    case ProbeFailure::busy: return "camera busy";
    case ProbeFailure::disconnected: return "camera disconnected";
    case ProbeFailure::timeout: return "camera timeout";
    case ProbeFailure::bad_frame: return "unusable frames";
    case ProbeFailure::config: return "camera configuration rejected";
  }
  return "camera failure";
}

void log_probe_line(LogPriority priority, const std::string& line) { log_line("weft probe", priority, line); }

namespace {

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// Irradiance of the map at ±X, ±Y, ±Z (mean over channels): a cheap summary of the light a
// surface sees, to tell a changed scene from sensor noise.
std::array<double, 6> axis_irradiance(const EnvMap& map) {
  static const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::array<double, 6> e{};
  for (int y = 0; y < map.height; ++y) {
    const double omega = map.solid_angle(y);
    for (int x = 0; x < map.width; ++x) {
      const glm::dvec3 d = map.direction(x, y);
      const glm::vec3& L = map.at(x, y);
      const double l = (L.r + L.g + L.b) / 3.0 * omega;
      for (int a = 0; a < 6; ++a) e[a] += l * std::max(glm::dot(d, axes[a]), 0.0);
    }
  }
  return e;
}

}  // namespace

LightProbeUpdater::LightProbeUpdater(LightProbeSource& source, LightProbeConfig config, SgLighting stored, Log log, Now now)
    : source_(source), config_(std::move(config)), sgs_(std::move(stored)), log_(log ? std::move(log) : Log(log_probe_line)),
      now_(now ? std::move(now) : Now([] { return Clock::now(); })), shortest_(config_.shortest) {
  if (config_.stops < 1 || !(config_.stop_spacing > 0) || config_.map_width < 8 || !(config_.smoothing > 0 && config_.smoothing <= 1))
    throw std::invalid_argument("light probe: bad configuration (stops ≥ 1, stop spacing > 0, map width ≥ 8, smoothing in (0, 1])");
  if (!config_.calibration.response.valid())
    throw std::invalid_argument("light probe: the camera response table must increase from ≥ 0 to 1");
}

void LightProbeUpdater::adjust_exposure(double factor) {
  const double longest_factor = std::exp2(config_.stop_spacing * (config_.stops - 1));
  shortest_.exposure_s = std::clamp(shortest_.exposure_s * factor, config_.min_exposure_s,
                                    std::max(config_.min_exposure_s, config_.max_exposure_s / longest_factor));
}

void LightProbeUpdater::fail(const ProbeError& error) {
  if (open_) source_.close();
  open_ = false;
  backoff_s_ = failing_ ? std::min(backoff_s_ * 2.0, config_.retry_max_s) : config_.retry_initial_s;
  retry_at_ = now_() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(backoff_s_));
  // One line when the probe enters a failure; silence while it persists (an unplugged camera
  // then reads as absent on every retry: still the same outage).
  if (!failing_) {
    std::ostringstream line;
    line << to_string(error.failure()) << ": " << error.what() << "; keeping the "
         << (fitted_ ? "last good camera lighting" : "stored lighting") << ", retrying with backoff (first in "
         << backoff_s_ << " s)";
    log_(LogPriority::warning, line.str());
  }
  failing_ = true;
  failure_kind_ = error.failure();
}

ProbeStepResult LightProbeUpdater::step() {
  if (failing_ && now_() < retry_at_) return ProbeStepResult::waiting;
  const auto t0 = Clock::now();
  ProbeTimings t;
  try {
    if (!open_) {
      source_.open();
      open_ = true;
    }
    std::vector<ProbeFrame> bracket;
    ProbeExposure e = shortest_;
    for (int i = 0; i < config_.stops; ++i) {
      bracket.push_back(source_.capture(e));
      e.exposure_s *= std::exp2(config_.stop_spacing);
    }
    t.capture_ms = ms_since(t0);

    auto t1 = Clock::now();
    BracketStats stats;
    HdrImage hdr;
    try {
      hdr = merge_bracket(bracket, config_.calibration, config_.ball, &stats);
    } catch (const ProbeError&) {
      // Steer the next bracket out of the black or the glare before retrying.
      if (config_.auto_exposure && stats.saturated_fraction > 0.5) adjust_exposure(std::exp2(-config_.stop_spacing * config_.stops));
      if (config_.auto_exposure && stats.black_fraction > 0.98) adjust_exposure(std::exp2(config_.stop_spacing * config_.stops));
      throw;
    }
    t.merge_ms = ms_since(t1);
    if (config_.auto_exposure) {
      // Put the brightest ball pixel of the shortest frame at 80 % of full scale (a small bright
      // lamp or the sun carries much of the irradiance: it must not clip); a clipped one is only
      // a lower bound, so step down a whole spacing then.
      if (stats.saturated_fraction > 0) adjust_exposure(std::exp2(-config_.stop_spacing));
      else if (stats.peak_sensor > 0) adjust_exposure(std::clamp(0.8 / stats.peak_sensor, 0.125, 8.0));
    }

    t1 = Clock::now();
    EnvMap map = unwrap_mirror_ball(hdr, config_.ball, config_.map_width, config_.map_width / 2);
    t.unwrap_ms = ms_since(t1);

    t1 = Clock::now();
    snapped_ = smoothed_.texels.size() != map.texels.size();
    if (!snapped_) {
      const auto e_new = axis_irradiance(map), e_old = axis_irradiance(smoothed_);
      double mean = 0, change = 0;
      for (int a = 0; a < 6; ++a) {
        mean += e_old[a] / 6.0;
        change = std::max(change, std::abs(e_new[a] - e_old[a]));
      }
      snapped_ = change > config_.snap_threshold * mean;
    }
    if (snapped_) smoothed_ = std::move(map);
    else {
      const float a = static_cast<float>(config_.smoothing);
      for (size_t i = 0; i < map.texels.size(); ++i) smoothed_.texels[i] += a * (map.texels[i] - smoothed_.texels[i]);
    }
    t.smooth_ms = ms_since(t1);

    t1 = Clock::now();
    const double cpu0 = thread_cpu_ms();
    SgLighting fitted = fit_sgs(smoothed_, config_.fit, fitted_ ? std::span<const SphericalGaussian>(sgs_)
                                                                 : std::span<const SphericalGaussian>(), &fit_stats_);
    t.fit_ms = ms_since(t1);
    t.fit_cpu_ms = thread_cpu_ms() - cpu0;
    sgs_ = std::move(fitted);
  } catch (const ProbeError& error) {
    fail(error);
    return ProbeStepResult::failed;
  }
  if (failing_) log_(LogPriority::info, std::string("camera back (") + source_.name() + "): lighting follows the room again");
  failing_ = false;
  fitted_ = true;
  backoff_s_ = 0;
  t.total_ms = ms_since(t0);
  timings_ = t;
  return ProbeStepResult::updated;
}

LightProbe::LightProbe(std::unique_ptr<LightProbeSource> source, LightProbeConfig config, SgLighting stored,
                       LightProbeUpdater::Log log)
    : source_(std::move(source)), updater_(*source_, config, stored, std::move(log)), config_(config), buffer_(stored) {}

LightProbe::~LightProbe() { stop(); }

void LightProbe::start() {
  if (thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    stopping_ = false;
  }
  thread_ = std::thread([this] { run(); });
}

void LightProbe::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  source_->close();
}

void LightProbe::run() {
  for (;;) {
    {
      std::lock_guard lock(mutex_);
      if (stopping_) return;
    }
    const auto started = Clock::now();
    const ProbeStepResult r = updater_.step();
    if (r == ProbeStepResult::updated) {
      buffer_.publish(updater_.sgs());
      updates_.fetch_add(1);
    }
    // Sleep until the retry is due (in backoff) or the pacing interval has passed; stop() wakes us.
    const auto until = r == ProbeStepResult::updated
                           ? started + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(config_.min_update_interval_s))
                           : updater_.retry_at();
    std::unique_lock lock(mutex_);
    wake_.wait_until(lock, until, [this] { return stopping_; });
  }
}

}  // namespace weft
