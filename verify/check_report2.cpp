// CheckReport2: collecting problems, merging reports, and printing them as JSON or text.
#include <cstdio>

#include "verify/checks2d.hpp"

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

}  // namespace

void CheckReport2::add_problem(std::string problem) {
  ok = false;
  ++problem_count;
  if (problems.size() < kMaxStoredProblems) problems.push_back(std::move(problem));
}

void CheckReport2::merge(const CheckReport2& other) {
  ok = ok && other.ok;
  problem_count += other.problem_count;
  for (const std::string& p : other.problems) {
    if (problems.size() >= kMaxStoredProblems) break;
    problems.push_back(p);
  }
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

std::string to_json(const CheckReport2& r) {
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

std::string to_text(const CheckReport2& r) {
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
