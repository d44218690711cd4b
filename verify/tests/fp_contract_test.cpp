// The kernel must be compiled without floating-point contraction: a fused multiply-add breaks
// the error analysis of the semi-static and dynamic filters. The probe a*b - c with
// a = b = 1 + 2^-30, c = 1 + 2^-29 is 0 when the product is rounded on its own (the 2^-60 of
// (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60 is lost) and 2^-60 when fused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "kernel/fp_contract_probe.hpp"

namespace {

constexpr double kA = 1.0 + 0x1p-30;
constexpr double kC = 1.0 + 0x1p-29;
constexpr double kFused = 0x1p-60;

// The probe expression, compiled here with contraction forced on, to show that the inputs tell
// a fused build from an unfused one. Contraction happens only when optimizing.
#if defined(__clang__)
__attribute__((target("fma"), noinline)) double contracted_probe(double a, double b, double c) {
#pragma clang fp contract(fast)
  return a * b - c;
}
#elif defined(__GNUC__)
#pragma GCC push_options
#pragma GCC optimize("fp-contract=fast")
__attribute__((target("fma"), noinline)) double contracted_probe(double a, double b, double c) {
  return a * b - c;
}
#pragma GCC pop_options
#endif

bool cpu_has_fma() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

TEST(FpContract, KernelProbeIsNotContracted) {
  // volatile: the inputs are unknown at compile time, so the kernel's own code computes it.
  volatile double a = kA, b = kA, c = kC;
  const double r = dtlab::detail::fp_contract_probe(a, b, c);
  EXPECT_EQ(r, 0.0) << "the kernel was compiled with floating-point contraction (probe returned "
                    << std::hexfloat << r << "); build it with -ffp-contract=off";
}

TEST(FpContract, KernelFlagsTurnContractionOff) {
  const std::string flags = dtlab::detail::kernel_compile_flags();
  EXPECT_NE(flags.find("-ffp-contract=off"), std::string::npos) << "kernel flags: " << flags;
}

TEST(FpContract, FusedEvaluationGivesTheOtherAnswer) {
  volatile double a = kA, b = kA, c = kC;
  EXPECT_EQ(std::fma(a, b, -c), kFused);  // std::fma is the correctly rounded fused operation
}

TEST(FpContract, ContractedCompilationIsDetected) {
  if (!cpu_has_fma()) GTEST_SKIP() << "this CPU has no FMA instructions";
#if !defined(__OPTIMIZE__)
  GTEST_SKIP() << "compilers contract a*b - c only when optimizing";
#else
  volatile double a = kA, b = kA, c = kC;
  EXPECT_EQ(contracted_probe(a, b, c), kFused) << "the probe would not catch a contracted kernel";
#endif
}

}  // namespace
