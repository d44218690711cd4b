// A probe that tells whether the kernel was compiled with floating-point contraction.
#pragma once

namespace dtlab::detail {

// Returns a * b - c rounded as two separate operations, as the kernel's filters assume. For
// a = b = 1 + 2^-30 and c = 1 + 2^-29 that is exactly 0; a build that fused it into an FMA
// returns 2^-60. Compiled with the kernel's flags (kernel/CMakeLists.txt).
double fp_contract_probe(double a, double b, double c) noexcept;

// The compiler flags the kernel was built with.
const char* kernel_compile_flags() noexcept;

}  // namespace dtlab::detail
