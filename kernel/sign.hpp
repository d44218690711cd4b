// The result of a predicate, and the result of a filter stage that may not decide.
#pragma once

#include <cstdint>
#include <optional>

namespace dtlab {

enum class Sign : std::int8_t { Negative = -1, Zero = 0, Positive = 1 };

constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
constexpr int to_int(Sign s) { return static_cast<int>(s); }
constexpr Sign sign_of(double v) {
  return v > 0.0 ? Sign::Positive : (v < 0.0 ? Sign::Negative : Sign::Zero);
}
constexpr const char* to_string(Sign s) {
  return s == Sign::Positive ? "positive" : (s == Sign::Negative ? "negative" : "zero");
}

// A filter stage either certifies the sign or says it cannot (std::nullopt).
using FilteredSign = std::optional<Sign>;

}  // namespace dtlab
