// The fit's tuning constants, in one place: every choice the statistics leave open, what it
// controls, and the evidence for its value (docs/fit.md, "Defaults", points to the tables in
// docs/results). Numerical tolerances (a hair below a distance, a search bound) stay with the code
// they protect; options a caller sets per fit (FitOptions, MleOptions, CalibrationOptions) start
// from these.
#pragma once

#include <array>
#include <cstddef>

namespace shapeproc::fit {

struct FitDefaults {
  // ---- Thresholds (fit_thresholds.hpp) ----
  // The half-width of a lattice shell's band, as a share of the exemplar's mean spacing
  // (|W| / n)^(1/dim).
  double shell_jitter = 0.1;
  // The smallest distance is a shell when as many of an axis's pairs as this share of the
  // elements, and shell_pairs at least, repeat it (a lattice's nearest neighbours: about one pair
  // per element).
  double shell_share = 0.25;
  std::size_t shell_pairs = 4;
  // Quantiles closer than this share of the shell half-width are one distance: a drawing's
  // lattice repeats its distances only up to the rounding of its coordinates (hexagons: 2.015 and
  // 2.020 px for one shell).
  double coincide = 0.2;
  // An axis's closest pair lies farther than the pair's closest over all axes by chance when its
  // pairs, drawn from the pooled distances, would all lie that far at least this often.
  double hard_core_level = 0.05;
  // A nested band reaches this many widths of the narrower category below zero at least (nested
  // pairs sit at minus one width or deeper; 1.1 leaves no sliver band between straddling and
  // nested pairs: data/corpus rims).
  double nested_depth = 1.1;

  // ---- Parameter budget (parameter_budget.hpp) ----
  // Exemplar pairs within a pair's range behind each γ: the low end of the 5–10 observations per
  // parameter rule.
  int pairs_per_parameter = 5;
  // The longest range, in mean spacings of the pair's denser category.
  double max_range_spacings = 2.5;
  // A pair whose every pseudo-likelihood γ is within this many standard errors of 1 keeps its
  // hard core alone (a Wald test at about 5%).
  double neutral_z = 2.0;
  // … but only where every γ's standard error on log γ is at most this: a larger one (a packed
  // exemplar's flat pseudo-likelihood, crescents-grid's 1e15) is no evidence of neutrality.
  double neutral_max_log_se = 1.0;

  // ---- Layers (category_layers.hpp) ----
  // A category is placed after a larger one when at least this share of its elements overlap or
  // lie inside that one's elements: most of them are decorations on bases (data/corpus rims,
  // edge-clusters: all of them; forest's mushrooms: all), not shapes that cross by chance.
  double layer_share = 0.5;
  // A layered category is anchored to its base (its intensity 0 off the base) when every one of
  // its elements overlaps a base or lies apart from one by at most this share of its median
  // radius: an overlap the drawing has and the proxies' chords lose (data/corpus edge-clusters:
  // 8 of its 100 decorations).
  double anchor_slack = 0.5;
  // A category of shapes whose median radius is at least this many times another's is placed
  // after it, overlapping or not: forest's trees (radius 30–42) among 400 grass discs were
  // never born into the grass when both were sampled at once (×0.001 of their density).
  double layer_size_ratio = 3.0;
  // Points are on a base point when closer than this share of the base category's mean spacing;
  // a category of points is placed after one with fewer points when every one of its points is
  // (under independence each would be with probability 1 − exp(−π/4) ≈ 0.54: data/corpus
  // cross-attraction's visitors, all within 5 of a host whose spacing is 15.8).
  double point_contact = 0.5;

  // ---- Saturation (saturation_choice.hpp) ----
  // A band is a candidate for saturation when its pseudo-likelihood γ is above 1 by more than
  // this many standard errors (a one-sided Wald test at about 2.5%).
  double saturation_z = 2.0;
  // The candidates' s: these quantiles of the exemplar's own counts per element in the band
  // (the elements with a neighbour there), and s = ∞.
  std::array<double, 4> saturation_quantiles{0.5, 0.75, 0.9, 1.0};
  // A saturated candidate replaces the pairwise model when its log pseudo-likelihood is higher by
  // at least this: Akaike's penalty for the one more parameter, s.
  double saturation_gain = 1.0;

  // ---- Estimator (fit_exemplar.hpp) ----
  // The maximum likelihood runs on tiles and on exemplars of at most this many elements: its
  // chains took over ten minutes at 460 elements, and half their iterations in 300 s on 100
  // overlapping discs; above, the pseudo-likelihood, checked on the output's scale
  // (docs/results/corpus.md).
  std::size_t likelihood_elements = 60;

  // ---- Maximum likelihood (fit_maximum_likelihood.hpp, mcmc_mle.hpp) ----
  // Starting values of log γ are kept within ± this: the pseudo-likelihood's estimate of a packed
  // exemplar may sit at the search bound, far from anything a sampler can reach.
  double start_bound = 3.0;
  // An automatic window's torus fit is abandoned for the window as drawn's start at its second
  // diverged step: rings diverged 3, 12 and 2 times in its 30 iterations at seeds 1–3, while the
  // data/ fits that converge from there diverged at most once.
  int abandon_torus_after = 2;
  // … and at once when its first simulation holds more than this many times the exemplar's
  // elements (rings' torus: 62–68 elements against 19 at seeds 1–3).
  double condensed_start = 2.0;
  // Chains that disagree more than this (R-hat) are not at one stationary state; their errors
  // are inflated by the disagreement.
  double max_r_hat = 1.1;
  // A gap within the tolerance counts only when every free statistic's sample is worth this many
  // independent observations (effective_sample_size.hpp).
  double min_effective_size = 20;
  // A crystal's search stops untested only where every category's expected count is within this
  // share of the exemplar's (cutout: held at 20.3 of 18 elements it gave outputs at ×1.5; tested
  // further, ×0.99).
  double held_crystal_share = 0.05;
  // The share of births proposed near a neighbour where the chains grow a lattice as a crystal
  // (a proposal: the stationary law does not depend on it).
  double crystal_near_birth_share = 0.5;
  // The most repeats a tile is refitted on (the quadrature grows with their square).
  int max_tile_repeats = 6;

  // ---- Shape classes (shape_classes.hpp) ----
  // A size class needs this many elements, and a category is cut into at most this many.
  int min_elements_per_class = 5;
  int max_size_groups = 8;

  // ---- Density check on the output's scale (density_calibration.hpp) ----
  // The torus: the exemplar's window times this along each axis.
  double calibration_multiple = 2.0;
  // A category agrees within this ratio, or two Poisson standard errors, whichever is wider.
  double calibration_tolerance = 0.08;
  // Chains at most; β changes by at most this factor per round.
  int calibration_rounds = 5;
  double calibration_largest_step = 8.0;
  // Over-dense categories whose count moved by less than this share of a β step (both in log)
  // are held up by the attraction, which is then shrunk (every log γ > 0 halved): under a
  // proportional law the share is 1, and amacrine's wide cross band gave 0.2.
  double calibration_least_elasticity = 0.5;
};

inline constexpr FitDefaults kFitDefaults{};

}  // namespace shapeproc::fit
