#pragma once
// Hands the latest AppearanceState from the input thread to the render thread without ever
// blocking the render thread: a seqlock. The (single) writer bumps the sequence to odd, stores
// the words, bumps it to even; a reader copies the words and keeps the copy only if the sequence
// was even and unchanged around it. All shared words are atomics, so there is no data race.
// A reader that keeps colliding with writes gives up after a few tries and keeps last frame's
// state — a frame never waits for a knob.
#include <atomic>
#include <cstdint>
#include <cstring>

#include "panel/appearance_state.h"

namespace weft::input {

class AppearanceChannel {
public:
  AppearanceChannel() { publish(AppearanceState{}); version_.store(0); }

  // Single writer (the input side serialises its writers).
  void publish(const AppearanceState& state) {
    uint64_t words[kWords] = {};
    std::memcpy(words, &state, sizeof state);
    const uint64_t s = sequence_.load(std::memory_order_relaxed);
    sequence_.store(s + 1, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_release);
    for (size_t i = 0; i < kWords; ++i) words_[i].store(words[i], std::memory_order_relaxed);
    sequence_.store(s + 2, std::memory_order_release);
    version_.fetch_add(1, std::memory_order_release);
  }

  // Increments with every publish; compare with the version of the last read to skip work.
  uint64_t version() const { return version_.load(std::memory_order_acquire); }

  // Wait-free for the reader: at most kTries attempts. Returns false (and leaves `out`) when
  // every attempt overlapped a write.
  bool read(AppearanceState& out, uint64_t* version = nullptr) const {
    for (int attempt = 0; attempt < kTries; ++attempt) {
      const uint64_t v = version_.load(std::memory_order_acquire);
      const uint64_t s1 = sequence_.load(std::memory_order_acquire);
      if (s1 & 1u) continue;
      uint64_t words[kWords];
      for (size_t i = 0; i < kWords; ++i) words[i] = words_[i].load(std::memory_order_relaxed);
      std::atomic_thread_fence(std::memory_order_acquire);
      if (sequence_.load(std::memory_order_relaxed) != s1) continue;
      std::memcpy(&out, words, sizeof out);
      if (version) *version = v;
      return true;
    }
    return false;
  }

private:
  static constexpr size_t kWords = (sizeof(AppearanceState) + 7) / 8;
  static constexpr int kTries = 16;
  std::atomic<uint64_t> sequence_{0};
  std::atomic<uint64_t> version_{0};
  std::atomic<uint64_t> words_[kWords];
};

}  // namespace weft::input
