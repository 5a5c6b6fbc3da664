#pragma once
// Where a frame's time goes, stage by stage: the backdrop, the Lambertian surfaces, the cloth's
// per-vertex passes and per-pixel draw, the weave layer, metering, and presenting. The code that
// draws a stage marks it with a StageScope; while a FrameProfile is recording a frame (between
// begin_frame and end_frame, on that thread) every scope splits the frame's time at its edges,
// and a nested scope's time is its own, not its parent's. With no profile recording a scope
// costs a thread-local read.
//
// Two clocks: GPU timestamps (EXT_disjoint_timer_query) where the driver has them, so a stage's
// figure is the GPU's time on it, read back after the frame; otherwise the CPU's steady clock
// around glFinish at each edge (on llvmpipe the CPU is the GPU, so this is its time, and finishing
// at each edge costs little there). Either way profiling serialises the frame a little: the
// stages add up to a bit more than an unprofiled frame.
#include <GLES3/gl3.h>

#include <array>
#include <chrono>
#include <string>
#include <vector>

namespace weft::gpu {

enum class Stage { backdrop, surfaces, vertex_pass, cloth, weave, metering, present, other };
inline constexpr int kStageCount = 8;
const char* stage_name(Stage s);

// EXT_disjoint_timer_query's entry points (an EGL context's: gpu/egl_context.h fetches them);
// all null where the driver has no timer queries.
struct TimerQueryFunctions {
  void (*query_counter)(GLuint id, GLenum target) = nullptr;
  void (*get_query_object_ui64)(GLuint id, GLenum pname, GLuint64* params) = nullptr;
  bool available() const { return query_counter && get_query_object_ui64; }
};

class FrameProfile {
public:
  enum class Clock { gpu_timestamps, cpu_finish };
  // Needs the GL context current. GPU timestamps when `timers` are available, else the CPU clock.
  explicit FrameProfile(TimerQueryFunctions timers = {});
  ~FrameProfile();
  FrameProfile(const FrameProfile&) = delete;
  FrameProfile& operator=(const FrameProfile&) = delete;

  Clock clock() const { return clock_; }
  const char* clock_name() const;

  // Records this thread's stages until end_frame, which adds the frame's per-stage times to the
  // samples (a frame the GPU reports as disjoint, e.g. after a power-state change, is dropped).
  void begin_frame();
  void end_frame();

  // Per stage: median milliseconds over the frames recorded since reset(); 0 for a stage never
  // entered. frames(): how many frames that is.
  std::array<double, kStageCount> median_ms() const;
  double median_total_ms() const;
  size_t frames() const { return totals_.size(); }
  void reset();
  // "backdrop 4.1, surfaces 1.0, ... (ms, median of N frames, cpu_finish)": stages never entered
  // left out.
  std::string summary() const;

  // The profile recording on this thread, or null.
  static FrameProfile* recording();

  // StageScope's edges.
  void push(Stage s);
  void pop();

private:
  void split();  // closes the interval since the last edge, charged to the stage on top
  Clock clock_;
  TimerQueryFunctions timers_;
  std::vector<Stage> stack_;
  // CPU clock: the last edge's time. GPU: the frame's queries and the stage each interval after
  // a query belongs to.
  std::chrono::steady_clock::time_point last_;
  std::vector<GLuint> pool_;
  size_t used_ = 0;
  std::vector<Stage> interval_stage_;
  std::array<double, kStageCount> frame_ms_{};
  std::array<std::vector<double>, kStageCount> samples_;
  std::vector<double> totals_;
};

// Marks a stage while a profile is recording on this thread; nothing otherwise.
class StageScope {
public:
  explicit StageScope(Stage s) : profile_(FrameProfile::recording()) {
    if (profile_) profile_->push(s);
  }
  ~StageScope() {
    if (profile_) profile_->pop();
  }
  StageScope(const StageScope&) = delete;
  StageScope& operator=(const StageScope&) = delete;

private:
  FrameProfile* profile_;
};

}  // namespace weft::gpu
