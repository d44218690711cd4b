// ProblemReport (problem_report.hpp): collecting problems and printing reports.
#include "verify/problem_report.hpp"

#include <cstdio>

namespace dtlab {

void ProblemReport::add_problem(std::string problem) {
  ok = false;
  ++problem_count;
  if (problems.size() < kMaxStoredProblems) problems.push_back(std::move(problem));
}

void ProblemReport::add_problems(const ProblemReport& other, std::string_view suffix) {
  ok = ok && other.ok;
  problem_count += other.problem_count;
  for (const std::string& p : other.problems) {
    if (problems.size() >= kMaxStoredProblems) break;
    problems.push_back(p + std::string(suffix));
  }
}

std::string json_string(std::string_view s) {
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

std::string report_json(const ProblemReport& r, const ReportCounts& counts, std::string_view extra) {
  std::string out = std::string("{\"ok\":") + (r.ok ? "true" : "false") +
                    ",\"problem_count\":" + std::to_string(r.problem_count) + ",\"counts\":{";
  for (std::size_t i = 0; i < counts.size(); ++i)
    out += (i ? ",\"" : "\"") + std::string(counts[i].first) + "\":" + std::to_string(counts[i].second);
  out += "}";
  out += extra;
  out += ",\"problems\":[";
  for (std::size_t i = 0; i < r.problems.size(); ++i) {
    if (i) out += ',';
    out += json_string(r.problems[i]);
  }
  return out + "]}";
}

std::string report_text(const ProblemReport& r, const ReportCounts& counts) {
  std::string out = r.ok ? "ok:" : std::to_string(r.problem_count) + " problems:";
  for (const auto& [key, value] : counts) out.append(" ").append(key).append("=").append(std::to_string(value));
  out += "\n";
  for (const std::string& p : r.problems) out += "  " + p + "\n";
  if (r.problems.size() < r.problem_count)
    out += "  ... and " + std::to_string(r.problem_count - r.problems.size()) + " more\n";
  return out;
}

}  // namespace dtlab
