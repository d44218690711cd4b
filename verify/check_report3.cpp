// CheckReport3: collecting problems, merging reports, and printing them as JSON or text.
#include <cstdio>

#include "verify/checks3d.hpp"

namespace dtlab {

namespace {

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

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

}  // namespace

void CheckReport3::add_problem(std::string problem) {
  ok = false;
  ++problem_count;
  if (problems.size() < kMaxStoredProblems) problems.push_back(std::move(problem));
}

void CheckReport3::merge(const CheckReport3& other) {
  ok = ok && other.ok;
  problem_count += other.problem_count;
  for (const std::string& p : other.problems) {
    if (problems.size() >= kMaxStoredProblems) break;
    problems.push_back(p);
  }
  std::vector<std::size_t> theirs;
  for_each_count(other, [&](const char*, std::size_t value) { theirs.push_back(value); });
  std::size_t k = 0;
  for_each_count(*this, [&](const char*, std::size_t& mine) {
    if (theirs[k] != 0) mine = theirs[k];
    ++k;
  });
}

std::string to_json(const CheckReport3& r) {
  std::string out = std::string("{\"ok\":") + (r.ok ? "true" : "false") +
                    ",\"problem_count\":" + std::to_string(r.problem_count) + ",\"counts\":{";
  bool first = true;
  for_each_count(r, [&](const char* key, std::size_t value) {
    out += (first ? "\"" : ",\"") + std::string(key) + "\":" + std::to_string(value);
    first = false;
  });
  out += "},\"problems\":[";
  for (std::size_t i = 0; i < r.problems.size(); ++i) {
    if (i) out += ',';
    out += json_string(r.problems[i]);
  }
  return out + "]}";
}

std::string to_text(const CheckReport3& r) {
  std::string out = r.ok ? "ok:" : std::to_string(r.problem_count) + " problems:";
  for_each_count(r, [&](const char* key, std::size_t value) {
    out.append(" ").append(key).append("=").append(std::to_string(value));
  });
  out += "\n";
  for (const std::string& p : r.problems) out += "  " + p + "\n";
  if (r.problems.size() < r.problem_count) {
    out += "  ... and " + std::to_string(r.problem_count - r.problems.size()) + " more\n";
  }
  return out;
}

}  // namespace dtlab
