#include "gl/frame_profile.h"

#include <GLES2/gl2ext.h>

#include <algorithm>
#include <cstdio>

namespace weft::gpu {

namespace {
thread_local FrameProfile* t_recording = nullptr;

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + long(mid), v.end());
  return v[mid];
}
}  // namespace

const char* stage_name(Stage s) {
  switch (s) {
    case Stage::backdrop: return "backdrop";
    case Stage::surfaces: return "surfaces";
    case Stage::vertex_pass: return "vertex passes";
    case Stage::cloth: return "cloth";
    case Stage::weave: return "weave";
    case Stage::metering: return "metering";
    case Stage::present: return "present";
    case Stage::other: return "other";
  }
  return "?";
}

FrameProfile::FrameProfile(TimerQueryFunctions timers)
    : clock_(timers.available() ? Clock::gpu_timestamps : Clock::cpu_finish), timers_(timers) {}

FrameProfile::~FrameProfile() {
  if (t_recording == this) t_recording = nullptr;
  if (!pool_.empty()) glDeleteQueries(GLsizei(pool_.size()), pool_.data());
}

const char* FrameProfile::clock_name() const { return clock_ == Clock::gpu_timestamps ? "GPU timestamps" : "CPU clock, glFinish"; }

FrameProfile* FrameProfile::recording() { return t_recording; }

void FrameProfile::begin_frame() {
  t_recording = this;
  stack_.clear();
  frame_ms_.fill(0.0);
  used_ = 0;
  interval_stage_.clear();
  if (clock_ == Clock::gpu_timestamps) {  // reading the flag clears it: end_frame's reading is this frame's
    GLint disjoint = 0;
    glGetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);
  }
  split();
}

void FrameProfile::split() {
  const Stage top = stack_.empty() ? Stage::other : stack_.back();
  if (clock_ == Clock::cpu_finish) {
    glFinish();
    const auto now = std::chrono::steady_clock::now();
    if (!interval_stage_.empty())
      frame_ms_[size_t(interval_stage_.back())] += std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
    interval_stage_.assign(1, top);
    return;
  }
  if (used_ == pool_.size()) {
    pool_.resize(pool_.size() + 16);
    glGenQueries(16, pool_.data() + used_);
  }
  timers_.query_counter(pool_[used_++], GL_TIMESTAMP_EXT);
  interval_stage_.push_back(top);
}

void FrameProfile::push(Stage s) {
  split();
  stack_.push_back(s);
  interval_stage_.back() = s;
}

void FrameProfile::pop() {
  split();
  if (!stack_.empty()) stack_.pop_back();
  interval_stage_.back() = stack_.empty() ? Stage::other : stack_.back();
}

void FrameProfile::end_frame() {
  split();
  t_recording = nullptr;
  std::array<bool, kStageCount> entered{};
  if (clock_ == Clock::gpu_timestamps) {
    std::vector<GLuint64> stamps(used_, 0);
    for (size_t i = 0; i < used_; ++i) timers_.get_query_object_ui64(pool_[i], GL_QUERY_RESULT_EXT, &stamps[i]);
    GLint disjoint = 0;
    glGetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);
    if (disjoint) return;  // the timestamps straddle a clock change: not a frame to count
    for (size_t i = 0; i + 1 < used_; ++i) {
      const auto s = size_t(interval_stage_[i]);
      frame_ms_[s] += double(stamps[i + 1] - stamps[i]) * 1e-6;
      entered[s] = true;
    }
  } else {
    for (int s = 0; s < kStageCount; ++s) entered[size_t(s)] = frame_ms_[size_t(s)] > 0.0;
  }
  double total = 0.0;
  for (int s = 0; s < kStageCount; ++s) {
    total += frame_ms_[size_t(s)];
    if (entered[size_t(s)] || !samples_[size_t(s)].empty()) samples_[size_t(s)].push_back(frame_ms_[size_t(s)]);
  }
  totals_.push_back(total);
}

std::array<double, kStageCount> FrameProfile::median_ms() const {
  std::array<double, kStageCount> out{};
  for (int s = 0; s < kStageCount; ++s) out[size_t(s)] = median_of(samples_[size_t(s)]);
  return out;
}

double FrameProfile::median_total_ms() const { return median_of(totals_); }

void FrameProfile::reset() {
  for (auto& s : samples_) s.clear();
  totals_.clear();
}

std::string FrameProfile::summary() const {
  const auto med = median_ms();
  std::string out;
  char buf[64];
  for (int s = 0; s < kStageCount; ++s) {
    if (samples_[size_t(s)].empty()) continue;
    std::snprintf(buf, sizeof buf, "%s%s %.1f", out.empty() ? "" : ", ", stage_name(Stage(s)), med[size_t(s)]);
    out += buf;
  }
  std::snprintf(buf, sizeof buf, " (ms, median of %zu frames, %s)", totals_.size(), clock_name());
  return out + buf;
}

}  // namespace weft::gpu
