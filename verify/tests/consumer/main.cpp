// Uses the installed package: predicates from the kernel, exact and perturbed.
#include <cstdio>

#include "kernel/predicates.hpp"

int main() {
  using dtlab::Vec2;
  const Vec2 a{0, 0}, b{1, 0}, c{0, 1}, d{1, 1};
  const bool ok = dtlab::orient2d(a, b, c) == dtlab::Sign::Positive &&
                  dtlab::incircle(a, b, c, d) == dtlab::Sign::Zero &&
                  dtlab::incircle_perturbed(a, b, c, d) != dtlab::Sign::Zero;
  std::printf("consumer: %s\n", ok ? "ok" : "WRONG");
  return ok ? 0 : 1;
}
