// The team of threads (kernel/worker_team.hpp): every index runs once per step, on each thread
// count (capped at the cores), step after step; the exception of the lowest failing index comes back, whatever the
// thread count, and the team still runs the next step; zero threads is refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
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

// for_each_share: contiguous shares in order covering [0, n) once, one per thread (one alone
// without a team), share k = [n k / shares, n (k + 1) / shares).
TEST(WorkerTeam, ForEachShareCoversTheRangeOnceInOrder) {
  WorkerTeam team(2);
  for (WorkerTeam* on : {static_cast<WorkerTeam*>(nullptr), &team}) {
    for (const std::size_t n : {0u, 1u, 5u, 1001u}) {
      const std::size_t count = shares(on);
      EXPECT_EQ(count, on == nullptr ? 1u : team.threads());
      std::vector<int> covered(n, 0);
      std::vector<std::pair<std::size_t, std::size_t>> range(count, {n + 1, n + 1});
      for_each_share(on, n, [&](std::size_t k, std::size_t begin, std::size_t end) {
        range[k] = {begin, end};
        for (std::size_t i = begin; i < end; ++i) ++covered[i];
      });
      for (std::size_t k = 0; k < count; ++k) {
        EXPECT_EQ(range[k].first, n * k / count) << "share " << k << " of " << count << ", n " << n;
        EXPECT_EQ(range[k].second, n * (k + 1) / count);
      }
      EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }));
    }
  }
}

}  // namespace
}  // namespace dtlab
