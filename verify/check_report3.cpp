// CheckReport3: collecting problems, merging reports, and printing them as JSON or text.
#include <cstdio>

#include "verify/checks3d.hpp"

namespace dtlab {

namespace {

// (name, member) of every count, in the order the printers and merge use.
template <class Report, class F>
void for_each_count(Report& r, F&& f) {
  f("points", r.points);
  f("tetrahedra", r.tetrahedra);
  f("hull_facets", r.hull_facets);
  f("referenced_points", r.referenced_points);
  f("interior_facets", r.interior_facets);
  f("edges", r.edges);
  f("hull_vertices", r.hull_vertices);
  f("duplicates", r.duplicates);
  f("insphere_tests", r.insphere_tests);
}

ReportCounts counts_of(const CheckReport3& r) {
  ReportCounts counts;
  for_each_count(r, [&](const char* key, std::size_t value) { counts.emplace_back(key, value); });
  return counts;
}

}  // namespace

void CheckReport3::merge(const CheckReport3& other) {
  add_problems(other);
  std::vector<std::size_t> theirs;
  for_each_count(other, [&](const char*, std::size_t value) { theirs.push_back(value); });
  std::size_t k = 0;
  for_each_count(*this, [&](const char*, std::size_t& mine) {
    if (theirs[k] != 0) mine = theirs[k];
    ++k;
  });
}

std::string to_json(const CheckReport3& r) { return report_json(r, counts_of(r)); }

std::string to_text(const CheckReport3& r) { return report_text(r, counts_of(r)); }

}  // namespace dtlab
