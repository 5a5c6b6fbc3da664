#pragma once
// body(i) for every i in [0, n), on all cores, each thread one contiguous block (OpenMP's
// schedule(static)): the per-vertex loops the kiosk runs at each lighting change. Plain
// std::thread rather than OpenMP so that the kiosk's binary, and its package, carry no OpenMP
// runtime (the offline rooms keep OpenMP). The indices must be independent. The first exception
// a block throws is rethrown here once every block has finished.
#include <algorithm>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace weft {

template <class Body>
void parallel_for(size_t n, Body&& body, size_t min_block = 64) {
  const size_t cores = std::max<size_t>(1, std::thread::hardware_concurrency());
  const size_t blocks = std::min(cores, (n + min_block - 1) / min_block);
  std::exception_ptr first;
  std::mutex first_mutex;
  auto run = [&](size_t b) {
    const size_t begin = n * b / blocks, end = n * (b + 1) / blocks;
    try {
      for (size_t i = begin; i < end; ++i) body(i);
    } catch (...) {
      std::lock_guard lock(first_mutex);
      if (!first) first = std::current_exception();
    }
  };
  if (blocks <= 1) {
    for (size_t i = 0; i < n; ++i) body(i);
    return;
  }
  {
    std::vector<std::jthread> threads;
    threads.reserve(blocks - 1);
    for (size_t b = 1; b < blocks; ++b) {
      try {
        threads.emplace_back(run, b);
      } catch (const std::system_error&) {
        run(b);  // no thread to be had (a tasks limit): this block on the caller's thread
      }
    }
    run(0);
  }  // joined
  if (first) std::rethrow_exception(first);
}

}  // namespace weft
