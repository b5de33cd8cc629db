#include "libshapeproc/evaluation/verdicts.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "libshapeproc/core/format.hpp"
#include "libshapeproc/metrics/wasserstein_test.hpp"

namespace shapeproc::evaluation {

namespace {

std::string number(double v, int digits = 2) { return core::format_fixed(v, digits); }

double total_intensity(const metrics::SceneStatistics& s) {
  double sum = 0.0;
  for (const double v : s.intensity) sum += v;
  return sum;
}

Verdict density(const std::string& metric, double ratio) {
  Verdict v{metric, ratio, "×" + number(ratio), "×0.8 to ×1.25", Outcome::pass, "", ""};
  if (!(ratio >= 0.8)) v.problem = "too sparse";
  if (ratio > 1.25) v.problem = "too dense";
  if (!v.problem.empty()) v.outcome = Outcome::fail;
  return v;
}

double overlap_share(const metrics::SceneStatistics& s) {
  return s.elements() > 0 ? static_cast<double>(s.collisions.elements) / s.elements() : 0.0;
}

double touching_per_element(const metrics::SceneStatistics& s) {
  return s.elements() > 0 ? static_cast<double>(s.collisions.touching.size()) / s.elements() : 0.0;
}

// Copied neighbourhoods against their chance level (metrics/novelty.hpp).
Verdict novelty(const metrics::Novelty& n) {
  const metrics::CopyMeasures& o = n.output;
  Verdict v{"novelty",
            o.patch,
            "patch copies " + number(o.patch) + " (chance " + number(n.chance.patch) +
                "), largest copied patch " + number(o.largest_patch) + ", copies " +
                number(o.copy) + " (chance " + number(n.chance.copy) + "), repetition " +
                number(o.repetition) + " (chance " + number(n.chance.repetition) + ")",
            "patch copies at most chance + " + number(metrics::kPatchExcess) +
                ", largest patch at most " + number(metrics::kLargestPatch),
            Outcome::pass,
            "",
            number(o.patch) + "/" + number(o.largest_patch)};
  if (n.lattice_exemplar) {
    v.outcome = Outcome::shown;
    v.rule = "shown: a lattice exemplar's own repeat is its only faithful arrangement";
  } else if (n.repeats_exemplar) {
    v.outcome = Outcome::fail;
    v.problem = "repeats the exemplar";
  }
  return v;
}

}  // namespace

ExemplarMeasures measure_exemplar(const geometry::Scene& exemplar, geometry::Boundary boundary,
                                  const metrics::SceneStatistics& statistics,
                                  const model::ShapeProcessModel* model) {
  ExemplarMeasures m;
  m.statistics = &statistics;
  m.order = metrics::bond_order(exemplar, boundary);
  m.kinds = shape_kinds(exemplar);
  m.model = model;
  m.scene = &exemplar;
  if (model) m.pairs = pair_counts(exemplar, boundary, *model);
  return m;
}

Judged measure_for_verdicts(const ExemplarMeasures& exemplar, const geometry::Scene& output,
                            geometry::Boundary output_boundary,
                            const metrics::SceneStatistics& output_statistics,
                            const metrics::Comparison& comparison,
                            const metrics::NeighbourhoodDistance* neighbourhood) {
  Judged j;
  j.exemplar = exemplar.statistics;
  j.output = &output_statistics;
  j.comparison = &comparison;
  j.neighbourhood = neighbourhood;
  j.exemplar_order = exemplar.order;
  j.output_order = metrics::bond_order(output, output_boundary);
  j.mix = shape_mix(exemplar.kinds, output);
  if (exemplar.scene && !exemplar.scene->elements.empty() && !output.elements.empty())
    j.novelty = metrics::measure_novelty(*exemplar.scene, output, output_boundary);
  if (exemplar.model)
    j.model = model_statistics(
        exemplar.pairs, pair_counts(output, output_boundary, *exemplar.model), *exemplar.model);
  return j;
}

Judged measure_for_verdicts(const geometry::Scene& exemplar, geometry::Boundary exemplar_boundary,
                            const metrics::SceneStatistics& exemplar_statistics,
                            const geometry::Scene& output, geometry::Boundary output_boundary,
                            const metrics::SceneStatistics& output_statistics,
                            const metrics::Comparison& comparison,
                            const metrics::NeighbourhoodDistance* neighbourhood,
                            const model::ShapeProcessModel* model) {
  return measure_for_verdicts(
      measure_exemplar(exemplar, exemplar_boundary, exemplar_statistics, model), output,
      output_boundary, output_statistics, comparison, neighbourhood);
}

namespace {

// The spacing check's tolerance where the samples are large enough that chance moves W1 less.
constexpr double kSpacingFloor = 0.15;
// The largest difference in the shares of a category inside or overlapping another that passes.
constexpr double kRelationTolerance = 0.15;

// The shape mix: the chi-square test of the classes' counts, naming the class that drifted most.
Verdict mix_verdict(const ShapeMix& mix) {
  Verdict v{"shape mix", mix.p_value, "p = " + number(mix.p_value, 3), "p ≥ 0.01", Outcome::pass,
            "",          ""};
  if (!(mix.p_value >= 0.01)) {
    v.outcome = Outcome::fail;
    v.problem = "the mix of shapes drifts";
  }
  v.brief = "p " + number(mix.p_value, 3);
  // Name the class that drifted most.
  double worst = 0.0;
  int total = 0, exemplar_total_count = 0;
  for (std::size_t c = 0; c < mix.classes.size(); ++c) {
    total += mix.output[c];
    exemplar_total_count += mix.exemplar[c];
  }
  for (std::size_t c = 0; c < mix.classes.size() && total > 0; ++c) {
    const double share = static_cast<double>(mix.output[c]) / total;
    const double wanted = static_cast<double>(mix.exemplar[c]) / exemplar_total_count;
    if (std::abs(share - wanted) > worst) {
      worst = std::abs(share - wanted);
      v.shown = "p = " + number(mix.p_value, 3) + " (" + mix.classes[c] + " " +
                number(100 * share, 0) + "% against " + number(100 * wanted, 0) + "%)";
    }
  }
  return v;
}

Verdict overlap_verdict(const metrics::SceneStatistics& o, const metrics::SceneStatistics& ex) {
  const double share = overlap_share(o), wanted = overlap_share(ex);
  Verdict v{"overlaps",
            share,
            number(100 * share, 1) + "% of elements",
            "at most the exemplar's " + number(100 * wanted, 1) + "% + 1",
            Outcome::pass,
            "",
            ""};
  if (share > wanted + 0.01) {
    v.outcome = Outcome::fail;
    v.problem = "elements overlap";
  }
  v.brief = number(100 * share, 1) + "%";
  return v;
}

// How elements sit on other categories' (inside, overlapping): the largest difference between
// the output's and the exemplar's shares over the categories both have, within 0.15.
std::optional<Verdict> relations_verdict(const metrics::SceneStatistics& o,
                                         const metrics::SceneStatistics& ex) {
  if (o.relations.empty() || ex.relations.empty()) return std::nullopt;
  double worst = 0.0;
  std::string where;
  for (std::size_t c = 0; c < o.categories.size(); ++c) {
    const auto e = std::find(ex.categories.begin(), ex.categories.end(), o.categories[c]);
    if (e == ex.categories.end()) continue;
    const auto k = static_cast<std::size_t>(e - ex.categories.begin());
    const double inside = std::abs(o.relations.nested[c] - ex.relations.nested[k]);
    const double across = std::abs(o.relations.overlapping[c] - ex.relations.overlapping[k]);
    if (std::max(inside, across) > worst) {
      worst = std::max(inside, across);
      where = o.categories[c] + (inside >= across ? " inside another" : " overlapping another");
    }
  }
  Verdict v{"relations",
            worst,
            where.empty() ? "0" : number(worst) + " (" + where + ")",
            "shares inside or overlapping another category within 0.15 of the exemplar's",
            Outcome::pass,
            "",
            ""};
  if (worst > kRelationTolerance) {
    v.outcome = Outcome::fail;
    v.problem = "elements sit on other categories unlike the exemplar's";
  }
  v.brief = number(worst);
  return v;
}

Verdict touching_verdict(const metrics::SceneStatistics& o, const metrics::SceneStatistics& ex) {
  const double per = touching_per_element(o), wanted = touching_per_element(ex);
  const double slack = std::max(0.1, 0.5 * wanted);
  Verdict v{"touching",
            per,
            number(per) + " pairs per element",
            number(wanted) + " ± " + number(slack),
            Outcome::pass,
            "",
            ""};
  if (std::abs(per - wanted) > slack) {
    v.outcome = Outcome::fail;
    v.problem = per > wanted ? "elements touch more often" : "contacts are lost";
  }
  v.brief = number(per);
  return v;
}

// Long-range order, of planar arrangements (a 3D scene's projection says little).
Verdict order_verdict(const Judged& j) {
  const double order = j.output_order.order(), wanted = j.exemplar_order.order();
  Verdict v{"order",
            order,
            number(order) + " (ψ" + std::to_string(j.output_order.symmetry()) + ")",
            number(wanted) + " ± 0.2",
            Outcome::pass,
            "",
            ""};
  if (std::abs(order - wanted) > 0.2) {
    v.outcome = Outcome::fail;
    v.problem = order < wanted ? "loses the exemplar's lattice" : "more regular than the exemplar";
  }
  v.brief = number(order);
  return v;
}

// Spacing: W1 of the nearest-neighbour distributions, against a fixed floor or, where the samples
// are small, the W1 two samples of their sizes from one distribution exceed 1% of the time.
Verdict spacing_verdict(const Judged& j) {
  const double w1 = j.comparison->all.nearest;
  const metrics::Distribution &out = j.output->all.nearest, &ref = j.exemplar->all.nearest;
  double chance = 0.0;
  metrics::WassersteinTest test;
  if (!out.empty() && !ref.empty() && out.samples > 0 && ref.samples > 0) {
    test = metrics::wasserstein_test(ref, out);
    chance = test.critical / j.comparison->scale;
  }
  const double limit = std::max(kSpacingFloor, chance);
  Verdict v{
      "spacing",
      w1,
      "W1 " + number(w1),
      "at most " + number(limit) + " (" +
          (chance > kSpacingFloor ? "the 1% chance level of " + std::to_string(test.sizes[0]) +
                                        " and " + std::to_string(test.sizes[1]) + " distances"
                                  : "the floor; the 1% chance level is " + number(chance)) +
          ")",
      Outcome::pass,
      "",
      ""};
  v.brief = number(w1);
  if (!(w1 <= limit)) {
    v.outcome = Outcome::fail;
    v.problem = "nearest distances differ";
  }
  return v;
}

// The fitted model's own statistics: pairs per band and element.
Verdict model_verdict(const ModelStatistics& m) {
  const auto w = static_cast<std::size_t>(m.worst);
  const double worst = std::abs(m.z[w]);
  Verdict v{
      "model statistics",
      worst,
      "|z| " + number(worst, 1) + " (" + m.names[w] + ": " + number(m.output[w]) + " against " +
          number(m.exemplar[w]) + " pairs per element)",
      "|z| ≤ " + number(m.critical, 1) + " (1% over " + std::to_string(m.z.size()) + " bands)",
      Outcome::pass,
      "",
      ""};
  v.brief = number(worst, 1);
  if (!(worst <= m.critical)) {
    v.outcome = Outcome::fail;
    v.problem = "pairs in a band differ";
  }
  return v;
}

}  // namespace

const char* to_string(Outcome outcome) {
  switch (outcome) {
    case Outcome::pass:
      return "pass";
    case Outcome::fail:
      return "fail";
    case Outcome::shown:
      break;
  }
  return "shown";
}

std::vector<Verdict> judge(const Judged& j) {
  std::vector<Verdict> out;
  const metrics::SceneStatistics& ex = *j.exemplar;
  const metrics::SceneStatistics& o = *j.output;

  // Density, overall and per category (where there are several).
  const double exemplar_total = total_intensity(ex);
  out.push_back(density("density", exemplar_total > 0 ? total_intensity(o) / exemplar_total : 0));
  if (o.categories.size() > 1 || ex.categories.size() > 1)
    for (std::size_t c = 0; c < o.categories.size(); ++c)
      if (c < j.comparison->intensity_ratio.size())
        out.push_back(density("density: " + o.categories[c], j.comparison->intensity_ratio[c]));

  if (j.mix.degrees > 0) out.push_back(mix_verdict(j.mix));

  out.push_back(overlap_verdict(o, ex));
  if (const std::optional<Verdict> relations = relations_verdict(o, ex)) out.push_back(*relations);
  out.push_back(touching_verdict(o, ex));

  if (ex.dimension == 2) out.push_back(order_verdict(j));

  out.push_back(spacing_verdict(j));

  if (j.model && j.model->worst >= 0) out.push_back(model_verdict(*j.model));

  if (j.novelty) out.push_back(novelty(*j.novelty));
  if (j.neighbourhood)
    out.push_back({"neighbourhood", j.neighbourhood->normalised,
                   number(j.neighbourhood->normalised) + " a²", "shown (lower is closer)",
                   Outcome::shown, "", ""});
  // The figure alone: what `shown` starts with, up to any explanation in brackets.
  for (Verdict& v : out) {
    if (!v.brief.empty()) continue;
    v.brief = v.shown.substr(0, v.shown.find(" ("));
  }
  return out;
}

std::string summary(const std::vector<Verdict>& verdicts) {
  std::string line;
  int checks = 0, failures = 0;
  for (const Verdict& v : verdicts) {
    if (v.outcome == Outcome::shown) continue;
    ++checks;
    if (v.outcome != Outcome::fail) continue;
    if (++failures > 3) continue;
    if (!line.empty()) line += "; ";
    line += v.metric + " " + v.shown + " (wanted " + v.rule + "): " + v.problem;
  }
  if (failures == 0) return "passes all " + std::to_string(checks) + " checks";
  if (failures > 3) line += "; and " + std::to_string(failures - 3) + " more";
  return "fails " + std::to_string(failures) + " of " + std::to_string(checks) + " checks: " + line;
}

}  // namespace shapeproc::evaluation
