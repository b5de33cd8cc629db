#include "libshapeproc/report/html_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/render/interaction_plot.hpp"
#include "libshapeproc/render/raster.hpp"

namespace shapeproc::report {

namespace {

const char* const kExemplarColour = "#222222";
const char* const kOutputColours[] = {"#d95f02", "#1b9e77", "#7570b3",
                                      "#e7298a", "#66a61e", "#e6ab02"};

std::string output_colour(std::size_t i) {
  return kOutputColours[i % (sizeof kOutputColours / sizeof *kOutputColours)];
}

// The page is well-formed XML (XHTML syntax), so that it can be checked by an XML parser.
std::string escape(const std::string& text) { return core::xml_escape(text); }

std::string num(double v, int precision = 4) {
  return std::isfinite(v) ? core::format_general(v, precision) : "–";
}

struct Series {
  std::string label, colour;
  std::vector<std::pair<double, double>> points;
  bool dashed = false;
};

// A line chart as inline SVG, axes from 0 to x_max and y_min to y_max.
std::string chart(const std::string& title, const std::string& x_label, double x_max, double y_min,
                  double y_max, const std::vector<Series>& series,
                  const std::vector<double>& reference_lines = {}) {
  const double w = 300, h = 200, left = 44, right = 10, top = 24, bottom = 34;
  const double pw = w - left - right, ph = h - top - bottom;
  auto X = [&](double x) { return left + pw * x / x_max; };
  auto Y = [&](double y) { return top + ph * (1.0 - (y - y_min) / (y_max - y_min)); };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
    << "\" viewBox=\"0 0 " << w << ' ' << h << "\" font-family=\"sans-serif\" font-size=\"10\">";
  s << "<text x=\"" << left << "\" y=\"14\" font-size=\"12\" font-weight=\"bold\">" << escape(title)
    << "</text>";
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#999\"/>";
  for (int k = 0; k <= 4; ++k) {
    const double x = x_max * k / 4, y = y_min + (y_max - y_min) * k / 4;
    s << "<text x=\"" << num(X(x), 5) << "\" y=\"" << num(top + ph + 12, 5)
      << "\" text-anchor=\"middle\">" << num(x, 3) << "</text>";
    s << "<text x=\"" << left - 4 << "\" y=\"" << num(Y(y) + 3, 5) << "\" text-anchor=\"end\">"
      << num(y, 3) << "</text>";
  }
  s << "<text x=\"" << num(left + pw / 2, 5) << "\" y=\"" << h - 4 << "\" text-anchor=\"middle\">"
    << escape(x_label) << "</text>";
  for (const double y : reference_lines) {
    s << "<line x1=\"" << left << "\" x2=\"" << left + pw << "\" y1=\"" << num(Y(y), 5)
      << "\" y2=\"" << num(Y(y), 5) << "\" stroke=\"#bbb\" stroke-dasharray=\"3 3\"/>";
  }
  for (const Series& line : series) {
    s << "<polyline fill=\"none\" stroke=\"" << line.colour << "\" stroke-width=\"1.5\""
      << (line.dashed ? " stroke-dasharray=\"5 3\"" : "") << " points=\"";
    for (const auto& [x, y] : line.points) {
      if (!std::isfinite(y)) continue;
      s << num(X(x), 5) << ',' << num(Y(std::clamp(y, y_min, y_max)), 5) << ' ';
    }
    s << "\"><title>" << escape(line.label) << "</title></polyline>";
  }
  s << "</svg>";
  return s.str();
}

Series cdf_series(const std::string& label, const std::string& colour,
                  const metrics::Distribution& d, double range) {
  Series s{label, colour, {}, false};
  if (d.empty()) return s;
  // A step function: a point just before and at each jump, on a fine grid.
  const int points = 240;
  for (int k = 0; k <= points; ++k) {
    const double x = range * k / points;
    s.points.emplace_back(x, d.cdf(x));
  }
  return s;
}

std::string legend(const Report& report) {
  std::ostringstream s;
  s << "<p class=\"legend\"><span style=\"color:" << kExemplarColour << "\">■</span> exemplar "
    << escape(report.exemplar.label);
  for (std::size_t i = 0; i < report.outputs.size(); ++i) {
    s << " &#160; <span style=\"color:" << output_colour(i) << "\">■</span> "
      << escape(report.outputs[i].label);
  }
  s << "</p>";
  return s.str();
}

std::string strip_xml_declaration(const std::string& svg) {
  const std::size_t start = svg.find("<svg");
  return start == std::string::npos ? svg : svg.substr(start);
}

// Each output's one-line summary, and a table of every check with its verdict per output.
void write_verdicts(const Report& report, std::ostringstream& html) {
  std::vector<std::string> metrics, rules;  // in order of first appearance
  bool any = false;
  for (const ReportScene& o : report.outputs) {
    if (!o.verdicts) continue;
    any = true;
    for (const evaluation::Verdict& v : *o.verdicts)
      if (std::find(metrics.begin(), metrics.end(), v.metric) == metrics.end()) {
        metrics.push_back(v.metric);
        rules.push_back(v.rule);
      }
  }
  if (!any) return;
  html << "<h2>Verdicts</h2>\n<ul>\n";
  for (std::size_t i = 0; i < report.outputs.size(); ++i) {
    const ReportScene& o = report.outputs[i];
    if (!o.verdicts) continue;
    const std::string line = evaluation::summary(*o.verdicts);
    const bool fails = line.rfind("fails", 0) == 0;
    html << "<li>output " << i + 1 << " (" << escape(o.label)
         << "): " << (fails ? "<span class=\"bad\">" : "<span class=\"good\">") << escape(line)
         << "</span></li>\n";
  }
  html << "</ul>\n<table>\n<tr><th>check</th><th>rule</th>";
  for (std::size_t i = 0; i < report.outputs.size(); ++i) html << "<th>output " << i + 1 << "</th>";
  html << "</tr>\n";
  for (std::size_t m = 0; m < metrics.size(); ++m) {
    html << "<tr><td>" << escape(metrics[m]) << "</td><td>" << escape(rules[m]) << "</td>";
    for (const ReportScene& o : report.outputs) {
      const evaluation::Verdict* found = nullptr;
      if (o.verdicts)
        for (const evaluation::Verdict& v : *o.verdicts)
          if (v.metric == metrics[m]) found = &v;
      if (!found) {
        html << "<td>–</td>";
        continue;
      }
      const char* mark = found->outcome == evaluation::Outcome::fail   ? "bad"
                         : found->outcome == evaluation::Outcome::pass ? "good"
                                                                       : "shown";
      html << "<td class=\"" << mark << "\">" << escape(found->shown)
           << (found->outcome == evaluation::Outcome::fail   ? " ✗ " + escape(found->problem)
               : found->outcome == evaluation::Outcome::pass ? std::string(" ✓")
                                                             : std::string())
           << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</table>\n<p>Each check's scale and rule: docs/metrics.md, \"Verdicts\".</p>\n";
}

// Every picture in one PNG, each output titled with its label and captioned with its verdict.
void write_overview(const Report& report, double scale, const std::filesystem::path& file) {
  std::vector<render::SheetPanel> panels;
  const auto panel = [&](const ReportScene& s, const std::string& title) {
    render::SheetPanel p;
    p.scene = s.scene;
    p.title = title;
    p.caption.push_back(std::to_string(s.statistics->elements()) + " elements");
    if (s.verdicts) p.caption.push_back(evaluation::summary(*s.verdicts));
    p.options.highlight = s.statistics->collisions.colliding;
    panels.push_back(std::move(p));
  };
  panel(report.exemplar, "exemplar");
  for (const ReportScene& o : report.outputs) panel(o, o.label);
  render::write_contact_sheet(panels, scale, file);
}

void require(const ReportScene& s) {
  if (!s.scene || !s.statistics)
    throw core::ArgumentError("report", "a scene or its statistics are missing");
}

}  // namespace

double picture_scale(const Report& report) {
  auto longest = [](const ReportScene& s) {
    const geometry::Vec3 size = s.scene->window.sizes();
    return std::max({size.x(), size.y(), 1e-12});
  };
  double scale = 420.0 / longest(report.exemplar);
  for (const ReportScene& o : report.outputs) scale = std::min(scale, 840.0 / longest(o));
  return scale;
}

namespace {

// The scenes in the report's order: the exemplar, then the outputs.
std::vector<const ReportScene*> scenes_of(const Report& report) {
  std::vector<const ReportScene*> scenes{&report.exemplar};
  for (const ReportScene& o : report.outputs) scenes.push_back(&o);
  return scenes;
}

// The pictures, one scale for all, colliding elements in red: their file names, in the scenes'
// order. Also the interaction plot and the overview.
std::vector<std::string> write_pictures(const Report& report, double scale,
                                        const std::filesystem::path& directory) {
  const std::vector<const ReportScene*> scenes = scenes_of(report);
  std::vector<std::string> pictures;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    render::RenderOptions options;
    options.scale = scale;
    options.highlight = scenes[i]->statistics->collisions.colliding;
    const std::string name = i == 0 ? "exemplar.png" : "output-" + std::to_string(i) + ".png";
    render::write_png(*scenes[i]->scene, directory / name, options);
    pictures.push_back(name);
  }
  if (report.model) render::write_interaction_plot(*report.model, directory / "interaction.svg");
  write_overview(report, scale, directory / "overview.png");
  return pictures;
}

void write_head(const Report& report, std::ostringstream& html) {
  html << "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" "
          "lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n"
       << "<title>shapeproc report: " << escape(report.exemplar.label) << "</title>\n<style>\n"
       << "body { font-family: sans-serif; margin: 2em; color: #222; max-width: 1400px; }\n"
       << "figure { display: inline-block; vertical-align: top; margin: 0 1.5em 1em 0; }\n"
       << "figcaption { font-size: 90%; color: #444; max-width: 840px; }\n"
       << "table { border-collapse: collapse; font-size: 90%; } td, th { border-bottom: 1px solid "
          "#ddd; padding: 3px 10px; text-align: right; }\n"
       << "th:first-child, td:first-child { text-align: left; } .charts svg { margin: 0 1em 1em 0; "
          "}\n"
       << ".bad { color: #c00; font-weight: bold; } .good { color: #070; } .legend { font-size: "
          "90%; } code { font-size: "
          "90%; }\n"
       << "</style>\n</head>\n<body>\n";
  html << "<h1>" << escape(report.exemplar.label) << " and " << report.outputs.size() << " output"
       << (report.outputs.size() == 1 ? "" : "s") << "</h1>\n";
  if (!report.command.empty()) html << "<p><code>" << escape(report.command) << "</code></p>\n";
}

void write_picture_section(const Report& report, double scale,
                           const std::vector<std::string>& pictures, std::ostringstream& html) {
  const std::vector<const ReportScene*> scenes = scenes_of(report);
  const std::string unit = report.exemplar.scene->units;
  html << "<h2>Pictures</h2>\n<p>One scale for all (" << num(scale, 3) << " px per " << escape(unit)
       << "); elements in a collision (shape distance 0) are drawn in red. All of them in one "
          "picture: <a href=\"overview.png\">overview.png</a>.</p>\n";
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const metrics::SceneStatistics& s = *scenes[i]->statistics;
    html << "<figure><img src=\"" << pictures[i] << "\" alt=\"" << escape(scenes[i]->label)
         << "\"/><figcaption>" << (i == 0 ? "exemplar " : "output ") << escape(scenes[i]->label)
         << ": " << s.elements() << " elements, "
         << (s.collisions.pairs.empty()
                 ? std::string("no collisions")
                 : "<span class=\"bad\">" + std::to_string(s.collisions.pairs.size()) +
                       " colliding pairs</span>");
    if (!scenes[i]->note.empty()) html << "<br/>" << escape(scenes[i]->note);
    html << "</figcaption></figure>\n";
  }
}

// The metrics table: one column per scene.
void write_metrics_table(const Report& report, std::ostringstream& html) {
  const std::vector<const ReportScene*> scenes = scenes_of(report);
  const metrics::SceneStatistics& ex = *report.exemplar.statistics;
  const std::string unit = report.exemplar.scene->units;
  const std::string area = unit + (ex.dimension == 2 ? "²" : "³");
  html << "<h2>Metrics</h2>\n<table>\n<tr><th>metric</th><th>exemplar</th>";
  for (std::size_t i = 0; i < report.outputs.size(); ++i) html << "<th>output " << i + 1 << "</th>";
  html << "</tr>\n";
  auto row = [&](const std::string& name, auto value) {
    html << "<tr><td>" << name << "</td>";
    for (std::size_t i = 0; i < scenes.size(); ++i)
      html << "<td>" << value(*scenes[i], i) << "</td>";
    html << "</tr>\n";
  };
  row("elements",
      [](const ReportScene& s, std::size_t) { return std::to_string(s.statistics->elements()); });
  row("boundary", [](const ReportScene& s, std::size_t) {
    const metrics::SceneStatistics& t = *s.statistics;
    return std::string(t.periodic()                               ? "torus"
                       : t.edge == metrics::EdgeTreatment::border ? "open, border-corrected"
                                                                  : "open");
  });
  for (std::size_t c = 0; c < ex.categories.size(); ++c) {
    row("intensity " + escape(ex.categories[c]) + " (per " + escape(area) + ")",
        [&](const ReportScene& s, std::size_t) {
          const metrics::SceneStatistics& t = *s.statistics;
          for (std::size_t k = 0; k < t.categories.size(); ++k) {
            if (t.categories[k] == ex.categories[c]) {
              std::string text = num(t.intensity[k]);
              if (s.comparison) text += " (×" + num(s.comparison->intensity_ratio[k], 3) + ")";
              return text;
            }
          }
          return std::string("–");
        });
  }
  row("collisions: pairs / elements", [](const ReportScene& s, std::size_t) {
    const metrics::Collisions& c = s.statistics->collisions;
    const std::string text =
        std::to_string(c.pairs.size()) + " / " + std::to_string(c.elements) + " (" +
        num(100.0 * c.elements / std::max(1, s.statistics->elements()), 3) + "%)";
    return c.pairs.empty() ? text : "<span class=\"bad\">" + text + "</span>";
  });
  row("mean nearest distance (" + escape(unit) + ")",
      [](const ReportScene& s, std::size_t) { return num(s.statistics->mean_nearest()); });
  row("neighbours within R",
      [](const ReportScene& s, std::size_t) { return num(s.statistics->all.neighbours, 3); });
  row("W1 nearest, all directions", [](const ReportScene& s, std::size_t) {
    return s.comparison ? num(s.comparison->all.nearest, 3) : std::string("0");
  });
  row("W1 nearest, worst axis", [](const ReportScene& s, std::size_t) {
    if (!s.comparison) return std::string("0");
    double worst = 0.0;
    for (const auto& a : s.comparison->axes)
      worst = std::max(worst, std::isfinite(a.nearest) ? a.nearest : 0.0);
    return num(worst, 3);
  });
  row("W1 pair distances, all directions", [](const ReportScene& s, std::size_t) {
    return s.comparison ? num(s.comparison->all.pairs, 3) : std::string("0");
  });
  row("neighbourhood distance (a²)", [](const ReportScene& s, std::size_t) {
    return s.neighbourhood ? num(s.neighbourhood->normalised, 3) : std::string("0");
  });
  html << "</table>\n<p>Distances are shape distances between proxies up to R = " << num(ex.range)
       << ' ' << escape(unit)
       << " (the exemplar's mean spacing a). W1: Wasserstein-1 distance to the exemplar's "
          "distribution divided by the "
          "exemplar's mean nearest distance. Neighbourhood distance: Davison et al. eq. 5 with Ma "
          "et al.'s eq. 1, "
          "divided by a². See docs/metrics.md.</p>\n";
}

// The model's sections: its interaction function, goodness of fit and envelopes.
void write_model_sections(const Report& report, std::ostringstream& html) {
  if (report.model) {
    html << "<h2>Interaction function</h2>\n<p>" << escape(report.model_label)
         << ": γ per axis and distance band (black: hard core, red: repulsion, blue: "
            "attraction).</p>\n"
         << strip_xml_declaration(render::interaction_plot_svg(*report.model)) << '\n';
  }
  if (!report.goodness.empty()) {
    html << "<h2>Goodness of fit</h2>\n<p>" << escape(report.goodness_note)
         << ". Each sufficient statistic of the exemplar against the fitted model's mean on the "
            "exemplar's window; z = (model − exemplar) / se, |z| above 3 in red.</p>\n<table>\n"
            "<tr><th>statistic</th><th>exemplar</th><th>model</th><th>se</th><th>z</th></tr>\n";
    for (const GoodnessRow& g : report.goodness) {
      const bool bad = std::abs(g.z) > 3.0;
      html << "<tr><td>" << escape(g.statistic) << (g.penalised ? " (attraction prior)" : "")
           << "</td><td>" << num(g.exemplar) << "</td><td>" << num(g.model) << "</td><td>"
           << num(g.standard_error, 2) << "</td><td" << (bad ? " class=\"bad\"" : "") << ">"
           << num(g.z, 2) << "</td></tr>\n";
    }
    html << "</table>\n";
  }
  if (!report.envelopes.empty()) {
    html << "<h3>Simulation envelopes</h3>\n<p>" << report.envelope_samples
         << " samples of the model on the exemplar's window: for each nearest-neighbour CDF, the "
            "share of distances in [0, R] where the exemplar's curve leaves the samples' "
            "pointwise band (a curve of the model itself leaves it with probability 2/"
         << report.envelope_samples + 1 << " at each distance). Passes at most "
         << num(100 * evaluation::kEnvelopeOutsideLimit, 3) << "%.</p>\n<table>\n"
         << "<tr><th>curve</th><th>outside the band</th></tr>\n";
    for (const evaluation::EnvelopeCurve& e : report.envelopes)
      html << "<tr><td>" << escape(e.label) << "</td><td class=\"" << (e.passes() ? "good" : "bad")
           << "\">" << num(100 * e.outside, 3) << "% " << (e.passes() ? "✓" : "✗")
           << "</td></tr>\n";
    html << "</table>\n";
  }
}

// The distance charts of every scene, overall and per axis, and the per-axis W1 table.
void write_distance_charts(const Report& report, std::ostringstream& html) {
  const metrics::SceneStatistics& ex = *report.exemplar.statistics;
  const std::string unit = report.exemplar.scene->units;
  html << "<h2>Distances</h2>\n" << legend(report) << "\n<div class=\"charts\">\n";
  const double range = ex.range;
  auto all_series = [&](auto pick) {
    std::vector<Series> series{cdf_series("exemplar", kExemplarColour, pick(ex), range)};
    for (std::size_t i = 0; i < report.outputs.size(); ++i) {
      series.push_back(cdf_series(report.outputs[i].label, output_colour(i),
                                  pick(*report.outputs[i].statistics), range));
    }
    return series;
  };
  html << chart("G(r): nearest neighbour", "shape distance r (" + unit + ")", range, 0, 1,
                all_series([](const metrics::SceneStatistics& s) -> const metrics::Distribution& {
                  return s.all.nearest;
                }));
  html << chart("pair distances below R", "shape distance r (" + unit + ")", range, 0, 1,
                all_series([](const metrics::SceneStatistics& s) -> const metrics::Distribution& {
                  return s.all.pairs;
                }));
  {
    std::vector<Series> series;
    double top = 2.0;
    auto g_series = [&](const std::string& label, const std::string& colour,
                        const metrics::SceneStatistics& s) {
      Series line{label, colour, {}, false};
      for (std::size_t k = 0; k < s.correlation.size(); ++k) {
        line.points.emplace_back(s.correlation_r[k], s.correlation[k]);
        if (std::isfinite(s.correlation[k]))
          top = std::max(top, std::min(6.0, s.correlation[k] * 1.1));
      }
      return line;
    };
    series.push_back(g_series("exemplar", kExemplarColour, ex));
    for (std::size_t i = 0; i < report.outputs.size(); ++i) {
      series.push_back(
          g_series(report.outputs[i].label, output_colour(i), *report.outputs[i].statistics));
    }
    html << chart("g(r): pair correlation", "shape distance r (" + unit + ")", range, 0,
                  std::ceil(top), series, {1.0});
  }
  html << "\n</div>\n<h3>Nearest neighbour per axis</h3>\n<div class=\"charts\">\n";
  for (std::size_t k = 0; k < ex.axes.size(); ++k) {
    const geometry::Vec3& d = ex.axes[k].direction;
    std::string title = "axis " + std::to_string(k) + " (" + num(d.x(), 2) + ", " + num(d.y(), 2);
    if (ex.dimension == 3) title += ", " + num(d.z(), 2);
    title += ")";
    html << chart(
        title, "shape distance (" + unit + ")", range, 0, 1,
        all_series([k](const metrics::SceneStatistics& s) -> const metrics::Distribution& {
          return s.axes.at(k).nearest;
        }));
  }
  html << "\n</div>\n";
  if (!report.outputs.empty()) {
    html << "<table>\n<tr><th>W1 nearest / pairs</th>";
    for (std::size_t k = 0; k < ex.axes.size(); ++k) html << "<th>axis " << k << "</th>";
    html << "</tr>\n";
    for (std::size_t i = 0; i < report.outputs.size(); ++i) {
      html << "<tr><td>output " << i + 1 << "</td>";
      for (const auto& a : report.outputs[i].comparison->axes)
        html << "<td>" << num(a.nearest, 3) << " / " << num(a.pairs, 3) << "</td>";
      html << "</tr>\n";
    }
    html << "</table>\n";
  }
}

}  // namespace

void write_report(const Report& report, const std::filesystem::path& directory) {
  require(report.exemplar);
  for (const ReportScene& o : report.outputs) require(o);
  std::filesystem::create_directories(directory);
  const double scale = picture_scale(report);
  const std::vector<std::string> pictures = write_pictures(report, scale, directory);
  std::ostringstream html;
  write_head(report, html);
  write_verdicts(report, html);
  write_picture_section(report, scale, pictures, html);
  write_metrics_table(report, html);
  write_model_sections(report, html);
  write_distance_charts(report, html);
  if (!report.timings.empty()) {
    html << "<h2>Timings</h2>\n<table>\n";
    for (const auto& [stage, seconds] : report.timings)
      html << "<tr><td>" << escape(stage) << "</td><td>" << num(seconds, 3) << " s</td></tr>\n";
    html << "</table>\n";
  }
  html << "<p class=\"legend\">Written by shapeproc " << SHAPEPROC_VERSION
       << ".</p>\n</body>\n</html>\n";
  core::write_file_atomically(directory / "index.html",
                              [&](std::ostream& out) { out << html.str(); });
}

}  // namespace shapeproc::report
