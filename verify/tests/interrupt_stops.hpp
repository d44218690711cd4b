// The expectation the meshers' interrupt tests share (mesh2d_test, mesh3d_test): a run whose
// check (kernel/interrupt.hpp) answers yes at its k-th question stops there, by Interrupted,
// naming the place.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "kernel/interrupt.hpp"

namespace dtlab::test {

// `run(check)` runs the algorithm with that check.
template <class Run>
void expect_interrupted_at(const Run& run, std::uint32_t at, const std::string& place) {
  std::uint32_t n = 0;
  try {
    run(InterruptCheck([&n, at] { return ++n == at; }));
    ADD_FAILURE() << "no Interrupted at question " << at;
  } catch (const Interrupted& e) {
    EXPECT_EQ(n, at);
    EXPECT_NE(std::string(e.what()).find(place), std::string::npos) << e.what();
  }
}

}  // namespace dtlab::test
