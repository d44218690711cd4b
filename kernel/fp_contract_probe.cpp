#include "kernel/fp_contract_probe.hpp"

namespace dtlab::detail {

double fp_contract_probe(double a, double b, double c) noexcept { return a * b - c; }

const char* kernel_compile_flags() noexcept { return DTLAB_KERNEL_FLAGS; }

}  // namespace dtlab::detail
