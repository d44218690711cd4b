// The team of threads (worker_team.hpp).
#include "kernel/worker_team.hpp"

#include <algorithm>

#include "kernel/error.hpp"

namespace dtlab {

namespace {

// At most one thread a core: a step waits for its slowest share, and a share whose thread is not
// running stalls all the others (measured: 4 threads on 2 cores, 20x the time of 2).
unsigned checked(unsigned threads) {
  if (threads == 0) throw InputError("threads: give at least 1");
  const unsigned cores = std::thread::hardware_concurrency();
  return cores > 0 ? std::min(threads, cores) : threads;
}

// Waiting: a few pauses (a hand-over between running threads takes less), a few yields, then
// sleep (C++20 atomic wait): on a loaded machine, where the thread a step waits for is not
// running, spinning longer only takes its core away (measured: seconds lost on 2 busy cores).
constexpr int kSpins = 256;
constexpr int kYields = 16;

inline void relax() noexcept {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

// Spins, then yields, while busy() holds, at most kSpins + kYields rounds; whether it still holds.
template <class F>
bool wait_while(F&& busy) {
  for (int k = 0; k < kSpins; ++k) {
    if (!busy()) return false;
    relax();
  }
  for (int k = 0; k < kYields; ++k) {
    if (!busy()) return false;
    std::this_thread::yield();
  }
  return busy();
}

}  // namespace

WorkerTeam::WorkerTeam(unsigned threads) : threads_(checked(threads)), errors_(threads_) {
  workers_.reserve(threads_ - 1);
  for (unsigned k = 1; k < threads_; ++k) workers_.emplace_back([this, k] { work(k); });
}

WorkerTeam::~WorkerTeam() {
  if (threads_ > 1) {
    stop_ = true;
    start_step();
  }  // the jthreads join
}

void WorkerTeam::start_step() {
  remaining_.store(threads_ - 1, std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_seq_cst);
  if (sleepers_.load(std::memory_order_seq_cst) > 0) generation_.notify_all();
}

void WorkerTeam::finish_share() {
  if (remaining_.fetch_sub(1, std::memory_order_seq_cst) == 1 && caller_sleeps_.load(std::memory_order_seq_cst))
    remaining_.notify_one();
}

void WorkerTeam::run_share(unsigned worker) {
  const std::size_t first = n_ * worker / threads_, end = n_ * (worker + 1) / threads_;
  errors_[worker] = nullptr;
  for (std::size_t i = first; i < end; ++i) {
    try {
      (*body_)(i, worker);
    } catch (...) {
      errors_[worker] = std::current_exception();
      return;
    }
  }
}

void WorkerTeam::work(unsigned worker) {
  std::uint64_t seen = 0;
  for (;;) {
    // Wait for the next step: spin, then sleep until generation_ moves on.
    wait_while([&] { return generation_.load(std::memory_order_acquire) == seen; });
    std::uint64_t now = generation_.load(std::memory_order_acquire);
    while (now == seen) {
      sleepers_.fetch_add(1, std::memory_order_seq_cst);
      if (generation_.load(std::memory_order_seq_cst) == seen) generation_.wait(seen, std::memory_order_seq_cst);
      sleepers_.fetch_sub(1, std::memory_order_seq_cst);
      now = generation_.load(std::memory_order_acquire);
    }
    seen = now;
    if (stop_) return;
    run_share(worker);
    finish_share();
  }
}

void WorkerTeam::run(std::size_t n, const Body& body) {
  body_ = &body;
  n_ = n;
  if (threads_ > 1) start_step();
  run_share(0);
  if (threads_ > 1 && wait_while([&] { return remaining_.load(std::memory_order_acquire) != 0; })) {
    caller_sleeps_.store(true, std::memory_order_seq_cst);
    for (unsigned left = remaining_.load(std::memory_order_seq_cst); left != 0;
         left = remaining_.load(std::memory_order_seq_cst))
      remaining_.wait(left, std::memory_order_seq_cst);
    caller_sleeps_.store(false, std::memory_order_relaxed);
  }
  body_ = nullptr;
  // Shares are contiguous and each stops at its first error: the lowest share with one holds the
  // lowest failing index.
  for (unsigned k = 0; k < threads_; ++k) {
    if (errors_[k]) std::rethrow_exception(errors_[k]);
  }
}

}  // namespace dtlab
