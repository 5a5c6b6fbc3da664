// The frame profiler (gl/frame_profile.h) on the CPU clock: a nested stage's time is its own,
// not its parent's as well; stages never entered are left out of the summary; scopes outside a
// recorded frame cost nothing and record nothing. Waits stand in for GPU work (each edge calls
// glFinish on a real context, which returns at once here).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "gl/frame_profile.h"
#include "gpu/egl_context.h"

using namespace weft;
using namespace std::chrono_literals;

TEST(FrameProfile, NestedStagesAreChargedOnceAndExclusively) {
  gpu::EglContext ctx = gpu::EglContext::headless();
  gpu::FrameProfile profile(gpu::TimerQueryFunctions{});
  ASSERT_EQ(profile.clock(), gpu::FrameProfile::Clock::cpu_finish);
  {
    const gpu::StageScope outside(gpu::Stage::backdrop);  // no frame recorded: nothing
    std::this_thread::sleep_for(5ms);
  }
  EXPECT_EQ(gpu::FrameProfile::recording(), nullptr);
  for (int frame = 0; frame < 3; ++frame) {
    profile.begin_frame();
    EXPECT_EQ(gpu::FrameProfile::recording(), &profile);
    {
      const gpu::StageScope cloth(gpu::Stage::cloth);
      std::this_thread::sleep_for(10ms);
      {
        const gpu::StageScope pass(gpu::Stage::vertex_pass);
        std::this_thread::sleep_for(60ms);
      }
      std::this_thread::sleep_for(10ms);
    }
    profile.end_frame();
  }
  EXPECT_EQ(gpu::FrameProfile::recording(), nullptr);
  EXPECT_EQ(profile.frames(), 3u);
  const auto ms = profile.median_ms();
  const double cloth = ms[size_t(gpu::Stage::cloth)], pass = ms[size_t(gpu::Stage::vertex_pass)];
  EXPECT_GE(pass, 59.0);
  EXPECT_GE(cloth, 19.0);
  EXPECT_LT(cloth, pass) << "the pass's 60 ms were charged to the cloth too";
  EXPECT_EQ(ms[size_t(gpu::Stage::backdrop)], 0.0);
  EXPECT_GE(profile.median_total_ms(), 79.0);  // every frame holds the 80 ms waited
  const std::string line = profile.summary();
  EXPECT_NE(line.find("vertex passes"), std::string::npos) << line;
  EXPECT_EQ(line.find("backdrop"), std::string::npos) << line;
  profile.reset();
  EXPECT_EQ(profile.frames(), 0u);
}
