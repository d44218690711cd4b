// What every checker's report shares (checks2d, checks3d, checks_constrained2d/3d): whether it
// passed, the problems found (the first kMaxStoredProblems kept, all counted), and the two ways
// of printing a report with its own counts: one JSON object, or a summary line and one problem
// per line. The JSON string escaping is the one the dtlab command uses too.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dtlab {

struct ProblemReport {
  static constexpr std::size_t kMaxStoredProblems = 1000;

  bool ok = true;
  std::vector<std::string> problems;  // at most kMaxStoredProblems
  std::size_t problem_count = 0;      // all problems found, stored or not

  void add_problem(std::string problem);
  // Appends other's problems (each followed by `suffix`) and their count, and its verdict.
  void add_problems(const ProblemReport& other, std::string_view suffix = {});
};

// s as a JSON string literal, quotes included.
std::string json_string(std::string_view s);

using ReportCounts = std::vector<std::pair<const char*, std::size_t>>;

// {"ok":true,"problem_count":0,"counts":{...}<extra>,"problems":[...]}; `extra`, if not empty,
// is inserted as is (",\"key\":value...").
std::string report_json(const ProblemReport& r, const ReportCounts& counts, std::string_view extra = {});
// "ok: key=value ..." or "N problems: key=value ...", then "  problem" lines and "  ... and N
// more" when some were not stored.
std::string report_text(const ProblemReport& r, const ReportCounts& counts);

}  // namespace dtlab
