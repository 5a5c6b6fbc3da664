#pragma once
// Hand-off of the newest SG lighting from the probe's worker to the render thread without
// either ever waiting: a triple buffer. The writer fills its back slot and swaps it with the
// middle one (one atomic exchange); the reader, once per frame, swaps its front slot with the
// middle one when a newer set is there (one atomic exchange). No locks, no allocation once the
// slots have the size of an SG set.
#include <array>
#include <atomic>
#include <cstdint>

#include "core/spherical_gaussian.h"

namespace weft {

class SgTripleBuffer {
public:
  explicit SgTripleBuffer(const SgLighting& initial = {}) { slots_.fill(initial); }

  // Writer side (one thread).
  void publish(const SgLighting& sgs) {
    slots_[back_] = sgs;
    back_ = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel) & kIndex;
  }

  // Reader side (one thread): takes the newest published set if there is one; true when the
  // front changed. Then read front() until the next acquire().
  bool acquire() {
    if (!(middle_.load(std::memory_order_acquire) & kFresh)) return false;
    front_ = middle_.exchange(front_, std::memory_order_acq_rel) & kIndex;
    ++generation_;
    return true;
  }
  const SgLighting& front() const { return slots_[front_]; }
  uint64_t generation() const { return generation_; }  // how many new sets the reader took

private:
  static constexpr uint32_t kIndex = 3, kFresh = 4;
  std::array<SgLighting, 3> slots_;
  std::atomic<uint32_t> middle_{1};
  uint32_t back_ = 0;   // writer's
  uint32_t front_ = 2;  // reader's
  uint64_t generation_ = 0;
};

}  // namespace weft
