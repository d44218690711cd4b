// A fixed team of threads that runs one data-parallel step at a time: body(i, worker) for every
// i in [0, n), the indices cut into one contiguous share per thread (the calling thread takes
// share 0). The threads live as long as the team (no thread start a step) and wait for the next
// step by spinning briefly, then sleeping (C++20 atomic wait). What a step computes must not
// depend on which worker runs an index: the worker number only picks per-thread scratch space
// (algorithms/mesh3d/field_point_regions: regions, each on whichever thread). An exception thrown
// by the body ends its share; the step still ends on every thread and run() rethrows the one of
// the lowest index, which is the one a single thread would have thrown first.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <thread>
#include <vector>

namespace dtlab {

class WorkerTeam {
 public:
  using Body = std::function<void(std::size_t index, unsigned worker)>;

  // threads >= 1 (InputError otherwise), capped at the hardware's thread count (threads());
  // one runs every step on the calling thread.
  explicit WorkerTeam(unsigned threads);
  ~WorkerTeam();
  WorkerTeam(const WorkerTeam&) = delete;
  WorkerTeam& operator=(const WorkerTeam&) = delete;

  unsigned threads() const noexcept { return threads_; }
  void run(std::size_t n, const Body& body);

 private:
  void run_share(unsigned worker);
  void work(unsigned worker);
  void start_step();
  void finish_share();

  unsigned threads_;
  const Body* body_ = nullptr;
  std::size_t n_ = 0;
  bool stop_ = false;
  std::atomic<std::uint64_t> generation_{0};  // one more a step; the workers wait for a change
  std::atomic<unsigned> sleepers_{0};         // workers in an atomic wait on generation_
  std::atomic<unsigned> remaining_{0};        // workers still in the current step
  std::atomic<bool> caller_sleeps_{false};    // run() in an atomic wait on remaining_
  std::vector<std::exception_ptr> errors_;
  std::vector<std::jthread> workers_;
};

// Runs fn(share, begin, end) for every share of [0, n) cut into `shares(team)` contiguous ranges,
// in order (share k holds [n k / shares, n (k + 1) / shares)): one per thread of `team`, or a
// single one on the calling thread when team is null. For loops whose result does not depend on
// how they are cut (per-share partial results are combined by the caller, in share order).
inline std::size_t shares(const WorkerTeam* team) noexcept { return team == nullptr ? 1 : team->threads(); }
template <class F>
void for_each_share(WorkerTeam* team, std::size_t n, F&& fn) {
  const std::size_t count = shares(team);
  if (count == 1) {
    fn(std::size_t{0}, std::size_t{0}, n);
    return;
  }
  team->run(count, [&](std::size_t k, unsigned) { fn(k, n * k / count, n * (k + 1) / count); });
}

}  // namespace dtlab
