// The team of threads (kernel/worker_team.hpp): every index runs once per step, on each thread
// count (capped at the cores), step after step; the exception of the lowest failing index comes back, whatever the
// thread count, and the team still runs the next step; zero threads is refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "kernel/error.hpp"
#include "kernel/worker_team.hpp"

namespace dtlab {
namespace {

TEST(WorkerTeam, RunsEveryIndexOncePerStep) {
  for (const unsigned threads : {1u, 2u, 3u, 5u}) {
    WorkerTeam team(threads);
    EXPECT_EQ(team.threads(), std::min(threads, std::max(1u, std::thread::hardware_concurrency())));
    for (const std::size_t n : {0u, 1u, 2u, 7u, 1000u}) {
      std::vector<std::atomic<int>> runs(n);
      std::vector<unsigned> worker_of(n, 99);
      team.run(n, [&](std::size_t i, unsigned worker) {
        runs[i].fetch_add(1);
        worker_of[i] = worker;
      });
      for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(runs[i].load(), 1) << threads << " threads, n " << n << ", index " << i;
        EXPECT_LT(worker_of[i], threads);
      }
    }
  }
}

TEST(WorkerTeam, RethrowsTheLowestFailingIndexAndGoesOn) {
  for (const unsigned threads : {1u, 2u, 4u}) {
    WorkerTeam team(threads);
    try {
      team.run(100, [](std::size_t i, unsigned) {
        if (i == 37 || i == 90) throw std::runtime_error("index " + std::to_string(i));
      });
      FAIL() << "no exception came back";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "index 37") << threads << " threads";
    }
    std::atomic<int> sum{0};
    team.run(10, [&](std::size_t i, unsigned) { sum += static_cast<int>(i); });
    EXPECT_EQ(sum.load(), 45);
  }
}

TEST(WorkerTeam, ZeroThreadsIsRefused) {
  try {
    WorkerTeam team(0);
    FAIL() << "a team of zero threads was made";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("threads"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dtlab
