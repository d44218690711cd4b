#include "kernel/stats.hpp"

namespace dtlab {

const char* to_string(Predicate p) noexcept {
  switch (p) {
    case Predicate::Orient2d: return "orient2d";
    case Predicate::Incircle: return "incircle";
    case Predicate::Orient3d: return "orient3d";
    case Predicate::Insphere: return "insphere";
  }
  return "unknown";
}

StageCounts& StageCounts::operator+=(const StageCounts& o) noexcept {
  semistatic += o.semistatic;
  adaptive += o.adaptive;
  exact += o.exact;
  perturbed += o.perturbed;
  gmp += o.gmp;
  return *this;
}

StageCounts& StageCounts::operator-=(const StageCounts& o) noexcept {
  semistatic -= o.semistatic;
  adaptive -= o.adaptive;
  exact -= o.exact;
  perturbed -= o.perturbed;
  gmp -= o.gmp;
  return *this;
}

StageCounts PredicateStats::total() const noexcept {
  StageCounts t;
  for (const StageCounts& c : counts) t += c;
  return t;
}

PredicateStats& PredicateStats::operator+=(const PredicateStats& o) noexcept {
  for (std::size_t i = 0; i < kPredicateCount; ++i) counts[i] += o.counts[i];
  return *this;
}

PredicateStats& PredicateStats::operator-=(const PredicateStats& o) noexcept {
  for (std::size_t i = 0; i < kPredicateCount; ++i) counts[i] -= o.counts[i];
  return *this;
}

std::string PredicateStats::to_json() const {
  std::string out = "{";
  for (std::size_t i = 0; i < kPredicateCount; ++i) {
    const StageCounts& c = counts[i];
    if (i) out += ',';
    out.append("\"").append(to_string(static_cast<Predicate>(i))).append("\":{\"semistatic\":");
    out.append(std::to_string(c.semistatic)).append(",\"adaptive\":").append(std::to_string(c.adaptive));
    out.append(",\"exact\":").append(std::to_string(c.exact)).append(",\"perturbed\":");
    out.append(std::to_string(c.perturbed)).append(",\"gmp\":").append(std::to_string(c.gmp)).append("}");
  }
  return out + "}";
}

}  // namespace dtlab
