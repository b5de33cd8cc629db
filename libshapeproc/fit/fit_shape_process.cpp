#include "libshapeproc/fit/fit_shape_process.hpp"

#include <algorithm>
#include <atomic>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "libshapeproc/fit/pseudo_likelihood.hpp"
#include "libshapeproc/fit/line_quadrature.hpp"
#include "libshapeproc/fit/quadrature_cell.hpp"
#include "libshapeproc/fit/quantile.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"

namespace shapeproc::fit {

using geometry::Element;
using geometry::Scene;
using geometry::Vec3;
using model::Interaction;

namespace {

// The existence check refits with this many times the data points' share and calls parameters
// whose logarithm moves by more than the tolerance unbounded.
constexpr double kExistenceFactor = 10.0;
constexpr double kExistenceTolerance = 0.01;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void check_options(const FitOptions& o) {
  if (o.thresholds.empty()) {
    if (o.quantiles.empty()) throw std::invalid_argument("fit: give at least one quantile order (q0)");
    for (std::size_t k = 0; k < o.quantiles.size(); ++k) {
      const double q = o.quantiles[k];
      if (!(q >= 0 && q <= 1)) throw std::invalid_argument("fit: quantile orders must be in [0, 1], got " + std::to_string(q));
      if (k > 0 && !(q > o.quantiles[k - 1])) {
        std::ostringstream text;
        text << "fit: quantile orders must increase, got " << q << " after " << o.quantiles[k - 1];
        throw std::invalid_argument(text.str());
      }
    }
  } else {
    for (std::size_t k = 0; k < o.thresholds.size(); ++k) {
      const double d = o.thresholds[k];
      if (!(std::isfinite(d) && d >= 0)) throw std::invalid_argument("fit: thresholds must be finite and >= 0");
      if (k > 0 && d < o.thresholds[k - 1]) {
        std::ostringstream text;
        text << "fit: thresholds must not decrease, got " << d << " after " << o.thresholds[k - 1];
        throw std::invalid_argument(text.str());
      }
    }
  }
  if (o.lines && o.refinement > 0) throw std::invalid_argument("fit: --refine applies to cells, not to --quadrature-lines");
  if (!(o.data_weight >= 0 && o.data_weight < 1)) throw std::invalid_argument("fit: the data points' weight must be in [0, 1)");
  if (o.quadrature < 0 || o.shapes_per_location < 0 || o.min_pairs_per_axis < 1) {
    throw std::invalid_argument("fit: quadrature, shapes per location and minimum pairs must be positive");
  }
}

std::vector<double> thresholds_from(std::vector<double> distances, const std::vector<double>& quantiles) {
  std::sort(distances.begin(), distances.end());
  std::vector<double> thresholds;
  for (double q : quantiles) thresholds.push_back(quantile(distances, q));
  return thresholds;
}

}  // namespace

const char* to_string(EdgeTreatment edge) {
  switch (edge) {
    case EdgeTreatment::none: return "none";
    case EdgeTreatment::periodic: return "periodic";
    case EdgeTreatment::border: return "border";
  }
  return "none";
}

FitResult fit_shape_process(const Scene& exemplar, const FitOptions& options) {
  check_options(options);
  if (exemplar.elements.empty()) throw std::invalid_argument("fit: the exemplar has no element");
  FitResult result;
  model::ShapeProcessModel& model = result.model;
  const int dimension = exemplar.dimension;
  if (options.lines && dimension != 2) throw std::invalid_argument("fit: --quadrature-lines is for 2D exemplars");
  model.dimension = dimension;
  model.units = exemplar.units;
  model.measurement.distance = options.distance;
  model.measurement.direction = options.direction;
  model.measurement.directions = options.directions > 0 ? options.directions : (dimension == 3 ? 12 : 8);
  model.measurement.proxy_tolerance = options.proxy_tolerance;
  const int categories = static_cast<int>(exemplar.categories.size());
  const std::vector<std::size_t> per_category = geometry::category_counts(exemplar);
  for (int c = 0; c < categories; ++c) {
    if (per_category[static_cast<std::size_t>(c)] == 0) {
      throw std::invalid_argument("fit: category '" + exemplar.categories[static_cast<std::size_t>(c)].name + "' has no element");
    }
    model.categories.push_back({exemplar.categories[static_cast<std::size_t>(c)].name, 1.0});
  }
  // Shape space per category: the distinct shapes of its elements.
  std::vector<std::vector<int>> shapes_of(static_cast<std::size_t>(categories));
  std::vector<int> shape_category(exemplar.shapes.size(), -1);
  for (const Element& e : exemplar.elements) {
    // A shape may serve several categories (the single point shape of a point pattern).
    if (shape_category[static_cast<std::size_t>(e.shape)] < 0) shape_category[static_cast<std::size_t>(e.shape)] = e.category;
    std::vector<int>& own = shapes_of[static_cast<std::size_t>(e.category)];
    if (std::find(own.begin(), own.end(), e.shape) == own.end()) own.push_back(e.shape);
  }
  bool points_only = true;
  for (const auto& shape : exemplar.shapes) points_only = points_only && geometry::dimension(shape) == 0;
  if (!points_only) {
    for (std::size_t s = 0; s < exemplar.shapes.size(); ++s) {
      model.shapes.push_back({exemplar.shapes[s], std::max(0, shape_category[s])});
    }
  }

  // Proxies and every pair's measurements.
  const bool periodic = options.edge == EdgeTreatment::periodic;
  auto clock = std::chrono::steady_clock::now();
  const geometry::PairMeasurer measurer(exemplar, model.measurement_options(periodic));
  result.seconds.proxies = seconds_since(clock);
  clock = std::chrono::steady_clock::now();
  const std::vector<geometry::PairRecord> pairs = measurer.all_pairs(exemplar.elements);
  result.seconds.measurements = seconds_since(clock);

  // Thresholds per category pair and axis.
  const int axes = measurer.bins().axis_count();
  std::vector<double> all_distances;
  std::map<std::pair<int, int>, std::vector<std::vector<double>>> by_pair;  // (a, b) -> per axis
  for (const geometry::PairRecord& p : pairs) {
    int a = exemplar.elements[static_cast<std::size_t>(p.i)].category;
    int b = exemplar.elements[static_cast<std::size_t>(p.j)].category;
    if (a > b) std::swap(a, b);
    auto& per_axis = by_pair[{a, b}];
    per_axis.resize(static_cast<std::size_t>(axes));
    per_axis[static_cast<std::size_t>(p.measurement.axis)].push_back(p.measurement.distance);
    all_distances.push_back(p.measurement.distance);
  }
  const bool fixed_thresholds = !options.thresholds.empty();
  if (!fixed_thresholds && all_distances.size() < 2) {
    result.notes.push_back("the exemplar has " + std::to_string(all_distances.size()) +
                           " pair(s) of elements: too few for thresholds, so the model is a Poisson process (no interaction)");
  } else {
    for (int a = 0; a < categories; ++a) {
      for (int b = a; b < categories; ++b) {
        model::PairInteraction pair;
        pair.first = a;
        pair.second = b;
        const auto found = by_pair.find({a, b});
        std::vector<double> pooled;
        if (found != by_pair.end())
          for (const auto& d : found->second) pooled.insert(pooled.end(), d.begin(), d.end());
        const std::string names = "'" + model.categories[static_cast<std::size_t>(a)].name + "'-'" +
                                  model.categories[static_cast<std::size_t>(b)].name + "'";
        bool noted_pool = false;
        for (int i = 0; i < axes; ++i) {
          model::AxisParameters axis;
          axis.direction = measurer.bins().axis_direction(i);
          if (fixed_thresholds) {
            axis.thresholds = options.thresholds;
          } else {
            const std::vector<double>* source = nullptr;
            if (found != by_pair.end() &&
                static_cast<int>(found->second[static_cast<std::size_t>(i)].size()) >= std::max(options.min_pairs_per_axis, 2)) {
              source = &found->second[static_cast<std::size_t>(i)];
            } else if (pooled.size() >= 2) {
              source = &pooled;
              if (!noted_pool) {
                result.notes.push_back("pair " + names + ": axes with fewer than " + std::to_string(options.min_pairs_per_axis) +
                                       " pairs take thresholds from the pair's " + std::to_string(pooled.size()) +
                                       " pairs pooled over all axes");
                noted_pool = true;
              }
            } else {
              source = &all_distances;
              if (!noted_pool) {
                result.notes.push_back("pair " + names + ": fewer than 2 pairs, thresholds from all " +
                                       std::to_string(all_distances.size()) + " pairs of the exemplar");
                noted_pool = true;
              }
            }
            axis.thresholds = thresholds_from(*source, options.quantiles);
          }
          const std::size_t bands = axis.thresholds.size() - 1;
          axis.gammas.assign(bands, 1.0);
          axis.gamma_standard_errors.assign(bands, std::numeric_limits<double>::quiet_NaN());
          axis.status.assign(bands, model::ParameterStatus::free);
          axis.observed_pairs.assign(bands, 0);
          pair.axes.push_back(std::move(axis));
        }
        model.interactions.push_back(std::move(pair));
      }
    }
  }
  const Interaction interaction(model);
  const double range = interaction.range();

  // Window of the sums: W, or W eroded by R for the border correction.
  geometry::Box3 region = exemplar.window;
  if (options.edge == EdgeTreatment::border) {
    for (int axis = 0; axis < dimension; ++axis) {
      region.min()[axis] += range;
      region.max()[axis] -= range;
      if (!(region.max()[axis] > region.min()[axis])) {
        throw std::invalid_argument("fit: --edge border leaves no window (the interaction range " + std::to_string(range) +
                                    " is at least half the window); use --edge none or periodic");
      }
    }
  }
  auto eligible = [&](const Vec3& p) {
    for (int axis = 0; axis < dimension; ++axis)
      if (p[axis] < region.min()[axis] || p[axis] > region.max()[axis]) return false;
    return true;
  };

  // Data statistics t(z_n | z \ z_n), and observed pairs per band.
  const std::size_t n = exemplar.elements.size();
  std::vector<model::InteractionCounts> data(n);
  for (const geometry::PairRecord& p : pairs) {
    const Element& a = exemplar.elements[static_cast<std::size_t>(p.i)];
    const Element& b = exemplar.elements[static_cast<std::size_t>(p.j)];
    const int band = interaction.band(a.category, b.category, p.measurement.axis, p.measurement.distance);
    if (band == Interaction::kHardCore) {
      std::ostringstream text;
      text << "fit: elements " << p.i << " and " << p.j << " are " << p.measurement.distance
           << " apart, below the hard-core distance d0 of their axis: lower the thresholds";
      throw std::invalid_argument(text.str());
    }
    if (band < 0) continue;
    const int parameter = interaction.parameter(a.category, b.category, p.measurement.axis, band);
    data[static_cast<std::size_t>(p.i)].add(parameter);
    data[static_cast<std::size_t>(p.j)].add(parameter);
    const Interaction::Location where = interaction.locate(parameter);
    ++model.interactions[static_cast<std::size_t>(where.pair)].axes[static_cast<std::size_t>(where.axis)]
          .observed_pairs[static_cast<std::size_t>(where.band)];
  }
  PseudoLikelihoodDesign design;
  design.parameter_count = interaction.parameter_count();
  design.data_sum.assign(static_cast<std::size_t>(design.parameter_count), 0.0);
  std::vector<int> eligible_per_category(static_cast<std::size_t>(categories), 0);
  for (std::size_t k = 0; k < n; ++k) {
    const Element& e = exemplar.elements[k];
    if (!eligible(e.position)) continue;
    ++result.data_points;
    ++eligible_per_category[static_cast<std::size_t>(e.category)];
    design.data_sum[static_cast<std::size_t>(e.category)] += 1.0;
    for (const auto& [parameter, count] : data[k].counts) design.data_sum[static_cast<std::size_t>(parameter)] += count;
  }
  for (int c = 0; c < categories; ++c) {
    if (eligible_per_category[static_cast<std::size_t>(c)] == 0) {
      throw std::invalid_argument("fit: --edge border keeps no element of category '" +
                                  model.categories[static_cast<std::size_t>(c)].name + "' (none lies " +
                                  std::to_string(range) + " inside the window)");
    }
  }

  // Quadrature: a grid of cells tiling the region, each cell crossed with m shapes of S_c (all,
  // or m in rotation), each dummy integrated over its cell (quadrature_cell.hpp) with weight
  // (1 − κ)|cell| / m, and the n_c data points of category c with κ|W| / n_c each (κ =
  // options.data_weight): the weights still sum to |W|, every observed statistic has exposure,
  // and the share does not shrink with the cells, so the maximum has a limit as they are refined
  // even on exemplars whose continuum LPL has no finite maximum (docs/fit.md).
  clock = std::chrono::steady_clock::now();
  const geometry::Vec3 sizes = region.sizes();
  const int cells_along = options.quadrature > 0 ? options.quadrature : (dimension == 3 ? 8 : 48);
  const double longest = sizes.head(dimension).maxCoeff();
  std::array<int, 3> count{1, 1, 1};
  double cell_measure = 1.0;
  result.quadrature_cells = 1;
  for (int axis = 0; axis < dimension; ++axis) {
    count[axis] = std::max(1, static_cast<int>(std::lround(sizes[axis] / longest * cells_along)));
    cell_measure *= sizes[axis] / count[axis];
    result.quadrature_cells *= count[axis];
  }
  auto cell_index = [&](const Vec3& p) {
    int index = 0;
    for (int axis = dimension - 1; axis >= 0; --axis) {
      const int k = std::clamp(static_cast<int>(std::floor((p[axis] - region.min()[axis]) / sizes[axis] * count[axis])), 0,
                               count[axis] - 1);
      index = index * count[axis] + k;
    }
    return index;
  };
  std::vector<std::vector<std::vector<int>>> data_in_cell(static_cast<std::size_t>(categories),
                                                         std::vector<std::vector<int>>(static_cast<std::size_t>(result.quadrature_cells)));
  std::vector<int> data_of_category(static_cast<std::size_t>(categories), 0);
  for (std::size_t k = 0; k < n; ++k) {
    const Element& e = exemplar.elements[k];
    if (!eligible(e.position)) continue;
    data_in_cell[static_cast<std::size_t>(e.category)][static_cast<std::size_t>(cell_index(e.position))].push_back(static_cast<int>(k));
    ++data_of_category[static_cast<std::size_t>(e.category)];
  }
  const double region_measure = cell_measure * result.quadrature_cells;
  struct Dummy {
    Element element;
    double weight;       // of the dummy's cell
    double line_weight;  // of the whole line through the cell, before the data points' share
  };
  std::vector<Dummy> dummies;
  std::vector<std::size_t> block_start;  // first dummy of each block of 4 rows of cells
  for (int c = 0; c < categories; ++c) {
    const std::vector<int>& shapes = shapes_of[static_cast<std::size_t>(c)];
    const int m_c = static_cast<int>(shapes.size());
    const int m = options.shapes_per_location > 0 ? std::min(m_c, options.shapes_per_location) : m_c;
    // With every shape at every location, shapes with the same proxy (copies of one drawing)
    // measure alike: one dummy stands for all of them, its weight multiplied.
    std::vector<std::pair<int, int>> distinct;  // (shape, copies)
    if (m == m_c) {
      for (const int shape : shapes) {
        auto same = std::find_if(distinct.begin(), distinct.end(),
                                 [&](const auto& d) { return measurer.same_proxy(d.first, shape); });
        if (same == distinct.end()) {
          distinct.push_back({shape, 1});
        } else {
          ++same->second;
        }
      }
    }
    for (int cell = 0; cell < result.quadrature_cells; ++cell) {
      if (cell % (4 * count[0]) == 0) block_start.push_back(dummies.size());
      Vec3 centre = Vec3::Zero();
      int rest = cell;
      for (int axis = 0; axis < dimension; ++axis) {
        const int k = rest % count[axis];
        rest /= count[axis];
        centre[axis] = region.min()[axis] + (k + 0.5) * sizes[axis] / count[axis];
      }
      const auto& inside = data_in_cell[static_cast<std::size_t>(c)][static_cast<std::size_t>(cell)];
      const int data_count = data_of_category[static_cast<std::size_t>(c)];
      const double data_share = data_count > 0 ? options.data_weight : 0.0;
      const double data_weight = data_count > 0 ? data_share * region_measure / data_count : 0.0;
      const double weight = (1 - data_share) * cell_measure / static_cast<double>(m);
      Element e;
      e.category = c;
      e.position = centre;
      if (!distinct.empty()) {
        for (const auto& [shape, copies] : distinct) {
          e.shape = shape;
          dummies.push_back({e, weight * copies, cell_measure / static_cast<double>(m) * copies * count[0]});
        }
      } else {
        for (int r = 0; r < m; ++r) {
          e.shape = shapes[static_cast<std::size_t>((static_cast<long>(cell) * m + r) % m_c)];
          dummies.push_back({e, weight, cell_measure / static_cast<double>(m) * count[0]});
        }
      }
      for (int k : inside) {
        QuadraturePoint q;
        q.weight = data_weight;
        q.category = c;
        q.counts = data[static_cast<std::size_t>(k)].counts;
        design.points.push_back(std::move(q));
      }
    }
  }
  block_start.push_back(dummies.size());
  const std::size_t data_in_quadrature = design.points.size();  // the data points come first
  // Each dummy integrated over its cell against the data, on two threads (results do not
  // depend on the thread count). With `lines` (2D), every row of cells becomes the line through
  // the cell centres, integrated exactly along its length (line_quadrature.hpp).
  double max_radius = 0.0;
  for (std::size_t s = 0; s < exemplar.shapes.size(); ++s) max_radius = std::max(max_radius, measurer.radius(static_cast<int>(s)));
  const int refinement = options.refinement;
  const bool lines = options.lines && range > 0;
  std::vector<std::vector<CellPart>> dummy_parts(dummies.size());
  // Runs evaluate(begin, step) on up to two threads, each taking every step-th dummy.
  const auto on_threads = [](const auto& evaluate) {
    const std::size_t threads = std::max(1u, std::min(2u, std::thread::hardware_concurrency()));
    std::vector<std::thread> workers;
    for (std::size_t t = 1; t < threads; ++t) workers.emplace_back(evaluate, t, threads);
    evaluate(0, threads);
    for (std::thread& w : workers) w.join();
  };
  if (lines) {
    LineContext context;
    context.interaction = &interaction;
    context.measurer = &measurer;
    context.data = &exemplar.elements;
    context.dimension = dimension;
    if (periodic) context.period = exemplar.window.sizes();
    context.tolerance = 1e-6 * longest;
    // Dummies of a row are its cells left to right; the first of each (category, row, shape)
    // carries the whole line, the others nothing.
    const double row_length = sizes.x();
    auto evaluate = [&](std::size_t begin, std::size_t step) {
      for (std::size_t d = begin; d < dummies.size(); d += step) {
        const Element& dummy = dummies[d].element;
        const int column = static_cast<int>(std::floor((dummy.position.x() - region.min().x()) / sizes.x() * count[0]));
        if (column != 0) continue;
        Vec3 start = dummy.position;
        start.x() = region.min().x();
        for (LinePiece& piece : integrate_line(context, dummy.category, dummy.shape, start, row_length)) {
          dummy_parts[d].push_back({piece.length / row_length, std::move(piece.counts)});
        }
      }
    };
    on_threads(evaluate);
  } else {
    geometry::NeighbourGrid grid(exemplar.window, dimension,
                              range + 2 * max_radius + std::sqrt(static_cast<double>(dimension)) * longest / cells_along, periodic);
    for (std::size_t k = 0; k < n; ++k) grid.insert(static_cast<int>(k), exemplar.elements[k].position);
    CellContext context{&interaction, &measurer, &exemplar.elements, &grid, dimension, Vec3::Zero()};
    if (periodic) context.period = exemplar.window.sizes();
    Vec3 cell_size = Vec3::Zero();
    for (int axis = 0; axis < dimension; ++axis) cell_size[axis] = sizes[axis] / count[axis];
    // Corners on a lattice fine enough for three levels of refinement, shared by the cells of a
    // block of rows that one thread integrates (the results do not depend on the blocks).
    context.lattice_origin = region.min();
    context.lattice_step = cell_size / 8.0;
    context.top_corner = 0.5 * cell_size.norm();
    std::atomic<std::size_t> next_block{0};
    auto evaluate = [&](std::size_t, std::size_t) {
      CornerCache cache;
      for (std::size_t b = next_block++; b + 1 < block_start.size(); b = next_block++) {
        cache.clear();
        for (std::size_t d = block_start[b]; d < block_start[b + 1]; ++d) {
          if (range <= 0) {
            dummy_parts[d] = {CellPart{}};
          } else {
            dummy_parts[d] = integrate_cell_adaptive(context, dummies[d].element, cell_size, refinement, &cache);
          }
        }
      }
    };
    on_threads(evaluate);
  }
  // Lines: the data points' share comes off every line of their category alike, so that the
  // weights still sum to |W|.
  std::vector<double> line_scale(static_cast<std::size_t>(categories), 1.0);
  if (lines) {
    const double measure = sizes.head(dimension).prod();
    for (const QuadraturePoint& q : design.points) line_scale[static_cast<std::size_t>(q.category)] -= q.weight / measure;
  }
  for (std::size_t d = 0; d < dummies.size(); ++d) {
    for (CellPart& part : dummy_parts[d]) {
      QuadraturePoint q;
      q.weight = lines ? dummies[d].line_weight * line_scale[static_cast<std::size_t>(dummies[d].element.category)] * part.fraction
                       : dummies[d].weight * part.fraction;
      q.category = dummies[d].element.category;
      q.counts = std::move(part.counts);
      design.points.push_back(std::move(q));
    }
  }
  result.quadrature_lines = lines;
  result.quadrature_points = static_cast<int>(design.points.size());
  // The same quadrature with ten times the data points' share (the existence check below).
  const bool check_existence = options.data_weight > 0 && kExistenceFactor * options.data_weight < 1;
  PseudoLikelihoodDesign heavier;
  if (check_existence) {
    heavier = design;
    const double dummy_scale = (1 - kExistenceFactor * options.data_weight) / (1 - options.data_weight);
    for (std::size_t i = 0; i < heavier.points.size(); ++i) heavier.points[i].weight *= i < data_in_quadrature ? kExistenceFactor : dummy_scale;
  }
  // Points with the same category and statistics contribute w·exp(θ·t) with the same t: merge
  // them (most dummies see no neighbour or the same few), in a deterministic order.
  const auto merge = [](PseudoLikelihoodDesign& d) {
    std::map<std::pair<int, std::vector<std::pair<int, int>>>, double> merged;
    for (QuadraturePoint& q : d.points) merged[{q.category, std::move(q.counts)}] += q.weight;
    d.points.clear();
    for (auto& [key, weight] : merged) d.points.push_back({weight, key.first, key.second});
  };
  merge(design);
  if (check_existence) merge(heavier);
  result.seconds.quadrature = seconds_since(clock);

  // Maximum pseudo-likelihood.
  clock = std::chrono::steady_clock::now();
  const double measure = sizes.head(dimension).prod();
  std::vector<double> start(static_cast<std::size_t>(design.parameter_count), 0.0);
  for (int c = 0; c < categories; ++c) {
    start[static_cast<std::size_t>(c)] = std::log(eligible_per_category[static_cast<std::size_t>(c)] / measure);
  }
  MpleResult mple = maximise_pseudo_likelihood(design, start);
  // Existence: where the continuum LPL has a maximum, the data points' tiny share hardly moves it
  // (below 0.3% on the shipped exemplars that have one); where it has none (packed exemplars:
  // no location with the data's neighbourhoods has positive measure), the share alone holds the
  // maximum and the estimates follow it (90–170%). Parameters that move are unbounded.
  bool follows_share = false;
  if (check_existence) {
    const MpleResult check = maximise_pseudo_likelihood(heavier, mple.theta);
    for (std::size_t p = 0; p < mple.theta.size(); ++p) {
      if (mple.status[p] != model::ParameterStatus::free) continue;
      if (std::abs(check.theta[p] - mple.theta[p]) > kExistenceTolerance) {
        follows_share = true;
        mple.status[p] = model::ParameterStatus::unbounded;
      }
    }
  }
  result.seconds.optimisation = seconds_since(clock);
  result.log_pseudo_likelihood = mple.log_pseudo_likelihood;
  for (int p = 0; p < design.parameter_count; ++p) {
    const double theta = mple.theta[static_cast<std::size_t>(p)];
    const double se = mple.standard_errors[static_cast<std::size_t>(p)];
    const Interaction::Location where = interaction.locate(p);
    if (where.pair < 0) {
      model::CategoryParameters& c = model.categories[static_cast<std::size_t>(where.axis)];
      c.beta = std::exp(theta);
      c.beta_status = mple.status[static_cast<std::size_t>(p)];
      c.beta_standard_error = c.beta_status == model::ParameterStatus::free ? c.beta * se : std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    model::AxisParameters& axis = model.interactions[static_cast<std::size_t>(where.pair)].axes[static_cast<std::size_t>(where.axis)];
    const std::size_t k = static_cast<std::size_t>(where.band);
    axis.status[k] = mple.status[static_cast<std::size_t>(p)];
    axis.gammas[k] = std::exp(theta);  // exp(−∞) = 0 on the boundary
    axis.gamma_standard_errors[k] = axis.status[k] == model::ParameterStatus::free ? axis.gammas[k] * se
                                                                                   : std::numeric_limits<double>::quiet_NaN();
  }
  if (follows_share) {
    result.notes.push_back("the pseudo-likelihood has no finite maximum without the data points' share of the quadrature: "
                           "no region of the window offers another element the neighbourhoods the elements have (a packed "
                           "exemplar, or one whose statistics are separated); the estimates follow that share (--data-weight), "
                           "and parameters that move with it are marked unbounded");
  }
  bool unbounded = false;
  for (model::ParameterStatus status : mple.status) unbounded = unbounded || status == model::ParameterStatus::unbounded;
  if (unbounded && !follows_share) {
    result.notes.push_back("some parameters have no finite maximum: the exemplar separates their statistics (for example "
                           "every element of a category near another category); they stay at the search bound |log gamma| = 30 "
                           "and are marked unbounded. Fewer bands (--quantiles), fewer directions or one category help.");
  }

  nlohmann::json fit = {
      {"window", {{"min", std::vector<double>(exemplar.window.min().data(), exemplar.window.min().data() + dimension)},
                  {"max", std::vector<double>(exemplar.window.max().data(), exemplar.window.max().data() + dimension)}}},
      {"elements", n},
      {"edge", to_string(options.edge)},
      {"quantiles", fixed_thresholds ? nlohmann::json() : nlohmann::json(options.quantiles)},
      {"thresholds", fixed_thresholds ? nlohmann::json(options.thresholds) : nlohmann::json()},
      {"quadrature", {{"method", result.quadrature_lines ? "lines" : "cells"}, {"cells", result.quadrature_cells}, {"cells_along_longest_side", cells_along},
                      {"shapes_per_location", options.shapes_per_location}, {"refinement", options.refinement},
                      {"points", result.quadrature_points}, {"data_weight", options.data_weight}}},
      {"data_points", result.data_points},
      {"log_pseudo_likelihood", result.log_pseudo_likelihood},
      {"optimiser", {{"method", "NLopt LD_LBFGS, then Newton"}, {"evaluations", mple.evaluations}, {"newton_steps", mple.newton_steps}}},
      {"notes", result.notes},
      {"seconds", {{"proxies", result.seconds.proxies}, {"measurements", result.seconds.measurements},
                   {"quadrature", result.seconds.quadrature}, {"optimisation", result.seconds.optimisation}}},
      {"version", SHAPEPROC_VERSION}};
  model.fit_json = fit.dump();
  return result;
}

}  // namespace shapeproc::fit
