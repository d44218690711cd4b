// CheckReport2: collecting problems, merging reports, and printing them as JSON or text.
#include <cstdio>

#include "verify/checks2d.hpp"

namespace dtlab {

namespace {

// (name, value) of every count, in the order both printers use.
template <class F>
void for_each_count(const CheckReport2& r, F&& f) {
  f("points", r.points);
  f("triangles", r.triangles);
  f("referenced_points", r.referenced_points);
  f("interior_edges", r.interior_edges);
  f("boundary_edges", r.boundary_edges);
  f("hull_points", r.hull_points);
  f("duplicates", r.duplicates);
  f("incircle_tests", r.incircle_tests);
}

ReportCounts counts_of(const CheckReport2& r) {
  ReportCounts counts;
  for_each_count(r, [&](const char* key, std::size_t value) { counts.emplace_back(key, value); });
  return counts;
}

}  // namespace

void CheckReport2::merge(const CheckReport2& other) {
  add_problems(other);
  const auto take = [](std::size_t& mine, std::size_t theirs) {
    if (theirs != 0) mine = theirs;
  };
  take(points, other.points);
  take(triangles, other.triangles);
  take(referenced_points, other.referenced_points);
  take(interior_edges, other.interior_edges);
  take(boundary_edges, other.boundary_edges);
  take(hull_points, other.hull_points);
  take(duplicates, other.duplicates);
  take(incircle_tests, other.incircle_tests);
}

std::string to_json(const CheckReport2& r) { return report_json(r, counts_of(r)); }

std::string to_text(const CheckReport2& r) { return report_text(r, counts_of(r)); }

}  // namespace dtlab
