#include "libshapeproc/render/interaction_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/constants.hpp"
#include "libshapeproc/core/format.hpp"

namespace shapeproc::render {

namespace {

// γ to colour: 0 → dark red, 1 → white, ≥ 4 → dark blue (log scale above 1).
std::string colour(double gamma) {
  double r, g, b;
  if (gamma <= 1.0) {
    const double t = std::clamp(gamma, 0.0, 1.0);
    r = 0.70 + 0.30 * t;
    g = 0.10 + 0.90 * t;
    b = 0.10 + 0.90 * t;
  } else {
    const double t = std::clamp(std::log(gamma) / std::log(4.0), 0.0, 1.0);
    r = 1.0 - 0.85 * t;
    g = 1.0 - 0.65 * t;
    b = 1.0 - 0.25 * t;
  }
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", static_cast<int>(r * 255),
                static_cast<int>(g * 255), static_cast<int>(b * 255));
  return text;
}

std::string fmt(double v) { return core::format_general(v, 4); }

// An annular sector between radii r0 < r1 and angles a0 < a1 (radians, y down as in SVG).
std::string sector(double cx, double cy, double r0, double r1, double a0, double a1) {
  auto point = [&](double r, double a) {
    return fmt(cx + r * std::cos(a)) + " " + fmt(cy + r * std::sin(a));
  };
  std::string d = "M" + point(r1, a0) + "A" + fmt(r1) + " " + fmt(r1) + " 0 0 1 " + point(r1, a1) +
                  "L" + point(r0, a1);
  if (r0 > 0) d += "A" + fmt(r0) + " " + fmt(r0) + " 0 0 0 " + point(r0, a0);
  return d + "Z";
}

}  // namespace

std::string interaction_plot_svg(const model::ShapeProcessModel& model) {
  const double size = 260, margin = 30;
  const double pairs = static_cast<double>(std::max<std::size_t>(1, model.interactions.size()));
  const double width = pairs * (size + margin) + margin, height = size + 2 * margin + 60;
  std::ostringstream svg;
  svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "width=\""
      << width << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << " " << height
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" "
         "fill=\"white\"/>\n";
  const double reach = std::max(model.interaction_range(), 1e-12);
  // Overlaps are distances below 0 (minus their depth): the radius starts at the deepest hard
  // core, so that an overlapping pair's bands show inside the circle drawn at contact.
  double lowest = 0.0;
  for (const model::PairInteraction& pair : model.interactions)
    for (const model::AxisParameters& a : pair.axes)
      lowest = std::min(lowest, a.thresholds.front());
  const auto share = [&](double d) {
    return std::clamp((d - lowest) / (reach - lowest), 0.0, 1.0);
  };
  for (std::size_t p = 0; p < model.interactions.size(); ++p) {
    const model::PairInteraction& pair = model.interactions[p];
    const double x0 = margin + static_cast<double>(p) * (size + margin), cx = x0 + size / 2,
                 cy = margin + size / 2;
    const double outer = size / 2 - 4;
    auto radius = [&](double d) { return outer * share(d) * 0.92; };
    svg << "<text x=\"" << cx << "\" y=\"" << margin - 10 << "\" text-anchor=\"middle\">"
        << core::xml_escape(model.categories[static_cast<std::size_t>(pair.first)].name) << " - "
        << core::xml_escape(model.categories[static_cast<std::size_t>(pair.second)].name)
        << "</text>\n";
    const std::size_t axes = pair.axes.size();
    if (model.dimension == 2) {
      svg << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << outer
          << "\" fill=\"white\" stroke=\"#999\"/>\n";
      const double half =
          axes <= 1 ? core::kPi
                    : core::kPi / (2.0 * static_cast<double>(axes));  // each direction spans 2π/D
      for (std::size_t i = 0; i < axes; ++i) {
        const model::AxisParameters& a = pair.axes[i];
        const double angle = std::atan2(a.direction.y(), a.direction.x());
        for (const double centre : {angle, angle + core::kPi}) {
          if (axes <= 1 && centre != angle) continue;
          const double a0 = centre - half, a1 = centre + half;
          svg << "<path d=\"" << sector(cx, cy, 0, radius(a.thresholds.front()), a0, a1)
              << "\" fill=\"black\"/>\n";
          for (std::size_t k = 0; k < a.gammas.size(); ++k) {
            const double r0 = radius(a.thresholds[k]), r1 = radius(a.thresholds[k + 1]);
            if (r1 <= r0) continue;
            svg << "<path d=\"" << sector(cx, cy, r0, r1, a0, a1) << "\" fill=\""
                << colour(a.gammas[k]) << "\" stroke=\"#555\" stroke-width=\"0.3\"><title>axis "
                << i << " band " << k + 1 << ": gamma " << fmt(a.gammas[k]) << " on ["
                << fmt(a.thresholds[k]) << ", " << fmt(a.thresholds[k + 1]) << ")</title></path>\n";
          }
        }
      }
      if (lowest < 0) {
        svg << "<circle cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << radius(0.0)
            << "\" fill=\"none\" stroke=\"#c00\" stroke-dasharray=\"2,2\"><title>contact: inside, "
               "overlaps</title></circle>\n";
      }
      svg << "<text x=\"" << cx << "\" y=\"" << cy + outer + 16
          << "\" text-anchor=\"middle\">radius: distance " << fmt(lowest) << " to " << fmt(reach)
          << " " << model.units << "</text>\n";
    } else {
      const double bar =
          std::min(24.0, size / static_cast<double>(std::max<std::size_t>(axes, 1)) - 4);
      for (std::size_t i = 0; i < axes; ++i) {
        const model::AxisParameters& a = pair.axes[i];
        const double y = margin + static_cast<double>(i) * (bar + 4);
        auto x = [&](double d) { return x0 + 40 + (size - 44) * share(d); };
        svg << "<text x=\"" << x0 << "\" y=\"" << y + bar * 0.7 << "\">axis " << i << "</text>\n";
        svg << "<rect x=\"" << x(lowest) << "\" y=\"" << y << "\" width=\""
            << x(a.thresholds.front()) - x(lowest) << "\" height=\"" << bar
            << "\" fill=\"black\"/>\n";
        for (std::size_t k = 0; k < a.gammas.size(); ++k) {
          svg << "<rect x=\"" << x(a.thresholds[k]) << "\" y=\"" << y << "\" width=\""
              << std::max(0.0, x(a.thresholds[k + 1]) - x(a.thresholds[k])) << "\" height=\"" << bar
              << "\" fill=\"" << colour(a.gammas[k])
              << "\" stroke=\"#555\" stroke-width=\"0.3\"/>\n";
        }
      }
    }
  }
  // Legend.
  const double ly = height - 40;
  svg << "<text x=\"" << margin << "\" y=\"" << ly - 6 << "\">gamma</text>\n";
  const double stops[] = {0, 0.25, 0.5, 0.75, 1, 1.5, 2, 3, 4};
  for (std::size_t k = 0; k < std::size(stops); ++k) {
    const double x = margin + static_cast<double>(k) * 34;
    svg << "<rect x=\"" << x << "\" y=\"" << ly << "\" width=\"34\" height=\"12\" fill=\""
        << colour(stops[k]) << "\" stroke=\"#555\" stroke-width=\"0.3\"/><text x=\"" << x + 17
        << "\" y=\"" << ly + 26 << "\" text-anchor=\"middle\">" << fmt(stops[k]) << "</text>\n";
  }
  svg << "<rect x=\"" << margin + 9 * 34 + 12 << "\" y=\"" << ly
      << "\" width=\"34\" height=\"12\" fill=\"black\"/><text x=\"" << margin + 9 * 34 + 50
      << "\" y=\"" << ly + 10 << "\">hard core</text>\n</svg>\n";
  return svg.str();
}

void write_interaction_plot(const model::ShapeProcessModel& model,
                            const std::filesystem::path& file) {
  const std::string text = interaction_plot_svg(model);
  core::write_file_atomically(file, [&](std::ostream& out) { out << text; });
}

}  // namespace shapeproc::render
