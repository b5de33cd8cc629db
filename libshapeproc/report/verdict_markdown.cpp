#include "libshapeproc/report/verdict_markdown.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/format.hpp"

namespace shapeproc::report {

void write_verdict_markdown(const Report& report, const std::filesystem::path& file) {
  std::vector<std::string> checks;
  for (const ReportScene& o : report.outputs)
    if (o.verdicts)
      for (const evaluation::Verdict& v : *o.verdicts)
        if (std::find(checks.begin(), checks.end(), v.metric) == checks.end())
          checks.push_back(v.metric);
  if (checks.empty()) return;
  core::write_file_atomically(file, [&](std::ostream& out) {
    out << "| output | elements | s |";
    for (const std::string& c : checks) out << ' ' << c << " |";
    out << "\n|---|---|---|";
    for (std::size_t i = 0; i < checks.size(); ++i) out << "---|";
    out << '\n';
    for (const ReportScene& o : report.outputs) {
      if (!o.verdicts) continue;
      std::string seconds = "–";
      for (const auto& [stage, s] : report.timings)
        if (stage == o.label) seconds = core::format_fixed(s, 1);
      out << "| " << o.label << " | " << (o.statistics ? o.statistics->elements() : 0) << " | "
          << seconds << " |";
      for (const std::string& c : checks) {
        const auto v = std::find_if(o.verdicts->begin(), o.verdicts->end(),
                                    [&](const evaluation::Verdict& x) { return x.metric == c; });
        if (v == o.verdicts->end()) {
          out << " – |";
          continue;
        }
        out << ' ' << v->brief
            << (v->outcome == evaluation::Outcome::fail   ? " ✗"
                : v->outcome == evaluation::Outcome::pass ? " ✓"
                                                          : "")
            << " |";
      }
      out << '\n';
    }
  });
}

}  // namespace shapeproc::report
