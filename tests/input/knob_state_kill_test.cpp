// Issue 9: `kill -9` at random moments during knob-state saves leaves the state file a valid old
// or new state, never a mix. A forked child saves states 1, 2, 3, ... as fast as it can through
// the same atomic write the KnobController uses; the parent kills it after a random delay and
// checks what is on disk. WEFT_KILL_ROUNDS overrides the number of rounds (default 1,000: about 5 s).
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "panel/knob_state_file.h"
#include "support/file_text.h"

namespace fs = std::filesystem;
using namespace weft::input;

namespace {

std::vector<PresetLook> presets() {
  PresetLook p;
  p.name = "linen_plain";
  p.albedo = {{{0.6, 0.5, 0.4}, {0.5, 0.5, 0.5}}};
  return {p};
}

KnobPositions state_number(int k) {
  KnobPositions s;
  s.hue_steps = {k % 97, -(k % 89)};
  s.brightness_steps = {k % 13, k % 7};
  s.gloss_steps = {-(k % 11), k % 5};
  s.env_steps = k;  // identifies the state
  return s;
}

using weft::test::read_all;

int rounds() {
  if (const char* r = std::getenv("WEFT_KILL_ROUNDS")) return std::atoi(r);
  return 1000;
}

}  // namespace

TEST(KnobStateKill, FileIsAlwaysAValidOldOrNewState) {
  const fs::path dir = fs::temp_directory_path() / ("weft_kill_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "knobs.json";
  const auto looks = presets();
  std::string why;
  ASSERT_TRUE(write_file_atomically(file, knob_state_text(state_number(0), looks), why)) << why;

  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> delay_us(0, 4000);
  int last_seen = 0, mid_write_kills = 0;
  const int n = rounds();
  for (int round = 0; round < n; ++round) {
    const int first = last_seen + 1;
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      std::string w;
      for (int k = first;; ++k) write_file_atomically(file, knob_state_text(state_number(k), looks), w);
    }
    usleep(delay_us(rng));
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);

    const std::string text = read_all(file);
    KnobPositions got;
    ASSERT_NO_THROW(got = parse_knob_state(text, looks)) << "round " << round << ": the state file is not valid:\n" << text;
    // It is the last state the previous round left, or one this child finished writing.
    const int k = got.env_steps;
    ASSERT_TRUE(k == last_seen || k >= first) << "round " << round << ": state " << k << " after " << last_seen;
    EXPECT_EQ(got, state_number(k)) << "round " << round << ": a mix of states";
    // Temporary files of killed writers may be left behind; they never replace the state.
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path() != file) {
        ++mid_write_kills;
        fs::remove(e.path());
      }
    last_seen = k;
  }
  // The kills landed both between and during writes (a left-behind temporary proves the latter).
  RecordProperty("mid_write_kills", mid_write_kills);
  std::printf("%d rounds, %d kills left a temporary file behind, last state %d\n", n, mid_write_kills, last_seen);
  EXPECT_GT(mid_write_kills, 0);
  EXPECT_GT(last_seen, 0);
  fs::remove_all(dir);
}
