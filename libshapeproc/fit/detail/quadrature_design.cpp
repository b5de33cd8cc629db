#include "libshapeproc/fit/detail/quadrature_design.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <map>
#include <thread>

#include "libshapeproc/core/parallel_for.hpp"
#include "libshapeproc/fit/anchored_quadrature.hpp"
#include "libshapeproc/fit/line_quadrature.hpp"
#include "libshapeproc/fit/point_counts.hpp"
#include "libshapeproc/fit/quadrature_cell.hpp"
#include "libshapeproc/geometry/neighbour_grid.hpp"

namespace shapeproc::fit {

using geometry::Element;
using geometry::Vec3;

namespace {

// Monte Carlo points around each base of an anchored category (anchored_quadrature.hpp). The
// integral over the part of a base's disc where the category may lie has a relative error of
// about 1/√(points there): 11% for one base whose ring holds a fifth of its disc, and β rests on
// the sum over the bases (4% over ten).
constexpr int kAnchoredPointsPerBase = 400;
constexpr int kMostSubdivisions = 8;
// Distinct shapes a category's cells are all crossed with by default; more take turns over the
// cells, 64 at each (longleaf's 584 trunk sizes: 1.3 million dummies, over a minute of
// quadrature, instead of 150,000). The Hero tiles have fewer.
constexpr int kMostDistinctShapes = 64;

using FitProgress = std::function<void(const char*, long long, long long)>;

// A dummy location with its shape, before integration.
struct Dummy {
  Element element;
  double weight;       // of the dummy's cell
  double line_weight;  // of the whole line through the cell, before the data points' share
};

// The grid of cells over the region.
struct CellGrid {
  std::array<int, 3> count{1, 1, 1};
  double cell_measure = 1.0;
  int cells = 1;
  int cells_along = 0;
  Vec3 sizes = Vec3::Zero();
  double longest = 0.0;

  CellGrid(const FitRegion& region, int cells_along_longest) : cells_along(cells_along_longest) {
    const int dimension = region.dimension;
    sizes = region.box.sizes();
    longest = sizes.head(dimension).maxCoeff();
    for (int axis = 0; axis < dimension; ++axis) {
      count[axis] = std::max(1, static_cast<int>(std::lround(sizes[axis] / longest * cells_along)));
      cell_measure *= sizes[axis] / count[axis];
      cells *= count[axis];
    }
  }

  int index_of(const FitRegion& region, const Vec3& p) const {
    int index = 0;
    for (int axis = region.dimension - 1; axis >= 0; --axis) {
      const int k = std::clamp(static_cast<int>(std::floor((p[axis] - region.box.min()[axis]) /
                                                           sizes[axis] * count[axis])),
                               0, count[axis] - 1);
      index = index * count[axis] + k;
    }
    return index;
  }

  Vec3 centre(const FitRegion& region, int cell) const {
    Vec3 centre = Vec3::Zero();
    int rest = cell;
    for (int axis = 0; axis < region.dimension; ++axis) {
      const int k = rest % count[axis];
      rest /= count[axis];
      centre[axis] = region.box.min()[axis] + (k + 0.5) * sizes[axis] / count[axis];
    }
    return centre;
  }
};

// Runs evaluate(begin, step) on `requested` threads (0: one per core), each taking every step-th
// item.
template <class F>
void on_threads(int requested, const F& evaluate) {
  const std::size_t threads = static_cast<std::size_t>(core::loop_threads(requested, 1 << 20));
  std::vector<std::thread> workers;
  for (std::size_t t = 1; t < threads; ++t) workers.emplace_back(evaluate, t, threads);
  evaluate(0, threads);
  for (std::thread& w : workers) w.join();
}

// With every shape at every location, shapes with the same proxy (copies of one drawing) measure
// alike: one dummy stands for all of them, its weight multiplied. Empty when only some shapes are
// used at each location.
std::vector<std::pair<int, int>> distinct_shapes(const std::vector<int>& shapes, int m,
                                                 const geometry::PairMeasurer& measurer) {
  std::vector<std::pair<int, int>> distinct;  // (shape, copies)
  if (m != static_cast<int>(shapes.size())) return distinct;
  for (const int shape : shapes) {
    auto same = std::find_if(distinct.begin(), distinct.end(),
                             [&](const auto& d) { return measurer.same_proxy(d.first, shape); });
    if (same == distinct.end()) {
      distinct.push_back({shape, 1});
    } else {
      ++same->second;
    }
  }
  return distinct;
}

// Every row of cells as the line through the cell centres, integrated exactly along its length.
// Dummies of a row are its cells left to right; the first of each (category, row, shape) carries
// the whole line, the others nothing.
void integrate_lines(const std::vector<Dummy>& dummies, const CellGrid& grid,
                     const FitRegion& region, const LineContext& context, int threads,
                     std::vector<std::vector<CellPart>>& parts) {
  const double row_length = grid.sizes.x();
  on_threads(threads, [&](std::size_t begin, std::size_t step) {
    for (std::size_t d = begin; d < dummies.size(); d += step) {
      const Element& dummy = dummies[d].element;
      const int column = static_cast<int>(
          std::floor((dummy.position.x() - region.box.min().x()) / grid.sizes.x() * grid.count[0]));
      if (column != 0) continue;
      Vec3 start = dummy.position;
      start.x() = region.box.min().x();
      for (LinePiece& piece :
           integrate_line(context, dummy.category, dummy.shape, start, row_length)) {
        parts[d].push_back({piece.length / row_length, std::move(piece.counts)});
      }
    }
  });
}

// Each dummy integrated over its cell, by blocks of 4 rows of cells that one thread takes at a
// time; corners on a lattice fine enough for three levels of refinement are shared by the cells
// of a block (the results do not depend on the blocks).
void integrate_cells(const std::vector<Dummy>& dummies, const std::vector<std::size_t>& block_start,
                     const CellGrid& grid, const FitRegion& region, CellContext context,
                     double range, int refinement, int threads, const FitProgress& progress,
                     std::vector<std::vector<CellPart>>& parts) {
  Vec3 cell_size = Vec3::Zero();
  for (int axis = 0; axis < region.dimension; ++axis)
    cell_size[axis] = grid.sizes[axis] / grid.count[axis];
  context.lattice_origin = region.box.min();
  context.lattice_step = cell_size / 8.0;
  context.top_corner = 0.5 * cell_size.norm();
  std::atomic<std::size_t> next_block{0}, done{0};
  const long long blocks = static_cast<long long>(block_start.size()) - 1;
  on_threads(threads, [&](std::size_t, std::size_t) {
    CornerCache cache;
    for (std::size_t b = next_block++; b + 1 < block_start.size(); b = next_block++) {
      if (progress) progress("quadrature", static_cast<long long>(done.load()), blocks);
      cache.clear();
      for (std::size_t d = block_start[b]; d < block_start[b + 1]; ++d) {
        parts[d] = range <= 0 ? std::vector<CellPart>{CellPart{}}
                              : integrate_cell_adaptive(context, dummies[d].element, cell_size,
                                                        refinement, &cache);
      }
      ++done;
    }
  });
  if (progress) progress("quadrature", blocks, blocks);
}

}  // namespace

namespace {

// The exemplar's elements in the region, by category and cell.
std::vector<std::vector<std::vector<int>>> data_by_cell(const geometry::Scene& exemplar,
                                                        const FitRegion& region,
                                                        const CellGrid& grid, int categories) {
  std::vector<std::vector<std::vector<int>>> data_in_cell(
      static_cast<std::size_t>(categories),
      std::vector<std::vector<int>>(static_cast<std::size_t>(grid.cells)));
  for (std::size_t k = 0; k < exemplar.elements.size(); ++k) {
    const Element& e = exemplar.elements[k];
    if (!region.contains(e.position)) continue;
    data_in_cell[static_cast<std::size_t>(e.category)]
                [static_cast<std::size_t>(grid.index_of(region, e.position))]
                    .push_back(static_cast<int>(k));
  }
  return data_in_cell;
}

// The dummies of every category and cell (at the cell's centre, one per distinct shape or per
// shape of the category), in blocks of 4 rows of cells (`block_start`: each block's first dummy,
// then the end); the data points join `design` in the same category and cell order.
std::vector<Dummy> place_dummies(const CellGrid& grid, const FitRegion& region,
                                 const FitOptions& options, const geometry::PairMeasurer& measurer,
                                 const ExemplarStatistics& statistics,
                                 const std::vector<std::vector<int>>& shapes_of,
                                 const std::vector<std::vector<std::vector<int>>>& data_in_cell,
                                 std::vector<std::size_t>& block_start,
                                 PseudoLikelihoodDesign& design) {
  const double region_measure = grid.cell_measure * grid.cells;
  std::vector<Dummy> dummies;
  for (int c = 0; c < static_cast<int>(shapes_of.size()); ++c) {
    const std::vector<int>& shapes = shapes_of[static_cast<std::size_t>(c)];
    const int m_c = static_cast<int>(shapes.size());
    int m = options.shapes_per_location > 0 ? std::min(m_c, options.shapes_per_location) : m_c;
    std::vector<std::pair<int, int>> distinct = distinct_shapes(shapes, m, measurer);
    // By default every distinct shape at every cell, up to a limit: beyond it the shapes take
    // turns over the cells.
    if (options.shapes_per_location == 0 &&
        distinct.size() > static_cast<std::size_t>(kMostDistinctShapes)) {
      m = kMostDistinctShapes;
      distinct.clear();
    }
    std::size_t data_count = 0;
    for (const std::vector<int>& in_cell : data_in_cell[static_cast<std::size_t>(c)])
      data_count += in_cell.size();
    const double data_share = data_count > 0 ? options.data_weight : 0.0;
    const double data_weight =
        data_count > 0 ? data_share * region_measure / static_cast<double>(data_count) : 0.0;
    const double weight = (1 - data_share) * grid.cell_measure / static_cast<double>(m);
    for (int cell = 0; cell < grid.cells; ++cell) {
      if (cell % (4 * grid.count[0]) == 0) block_start.push_back(dummies.size());
      Element e;
      e.category = c;
      e.position = grid.centre(region, cell);
      if (!distinct.empty()) {
        for (const auto& [shape, copies] : distinct) {
          e.shape = shape;
          dummies.push_back({e, weight * copies,
                             grid.cell_measure / static_cast<double>(m) * copies * grid.count[0]});
        }
      } else {
        for (int r = 0; r < m; ++r) {
          e.shape = shapes[static_cast<std::size_t>((static_cast<long>(cell) * m + r) % m_c)];
          dummies.push_back(
              {e, weight, grid.cell_measure / static_cast<double>(m) * grid.count[0]});
        }
      }
      for (int k : data_in_cell[static_cast<std::size_t>(c)][static_cast<std::size_t>(cell)]) {
        QuadraturePoint q;
        q.weight = data_weight;
        q.category = c;
        q.counts = statistics.per_element[static_cast<std::size_t>(k)].counts;
        design.points.push_back(std::move(q));
      }
    }
  }
  block_start.push_back(dummies.size());
  return dummies;
}

// Each dummy integrated against the data, by lines or by cells: its parts.
std::vector<std::vector<CellPart>> integrate_dummies(
    const std::vector<Dummy>& dummies, const std::vector<std::size_t>& block_start,
    const CellGrid& grid, const FitRegion& region, const geometry::Scene& exemplar,
    const FitOptions& options, const geometry::PairMeasurer& measurer,
    const model::Interaction& interaction, const geometry::Domain& window, bool lines) {
  const int dimension = region.dimension;
  const double range = interaction.range();
  double max_radius = 0.0;
  for (std::size_t s = 0; s < exemplar.shapes.size(); ++s)
    max_radius = std::max(max_radius, measurer.radius(static_cast<int>(s)));
  std::vector<std::vector<CellPart>> parts(dummies.size());
  const Vec3& period = window.period();
  if (lines) {
    LineContext context;
    context.interaction = &interaction;
    context.measurer = &measurer;
    context.data = &exemplar.elements;
    context.dimension = dimension;
    context.period = period;
    context.tolerance = 1e-6 * grid.longest;
    integrate_lines(dummies, grid, region, context, options.threads, parts);
    return parts;
  }
  geometry::NeighbourGrid neighbours(
      exemplar.window, dimension,
      range + 2 * max_radius +
          std::sqrt(static_cast<double>(dimension)) * grid.longest / grid.cells_along,
      window.periodic());
  for (std::size_t k = 0; k < exemplar.elements.size(); ++k)
    neighbours.insert(static_cast<int>(k), exemplar.elements[k].position);
  const CellContext context{&interaction, &measurer, &exemplar.elements,
                            &neighbours,  dimension, period};
  integrate_cells(dummies, block_start, grid, region, context, range, options.refinement,
                  options.threads, options.progress, parts);
  return parts;
}

// Sub-points per cell along each axis for a saturated model: spaced at most a twelfth of the
// interaction range apart, at most kMostSubdivisions.
int saturated_subdivisions(const CellGrid& grid, const model::Interaction& interaction) {
  const double step = interaction.range() / 12.0;
  const double cell = grid.longest / grid.cells_along;
  return std::clamp(static_cast<int>(std::ceil(cell / step)), 1, kMostSubdivisions);
}

// Each dummy's cell sampled at sub-points (point_counts.hpp).
std::vector<std::vector<CellPart>> sample_dummies(const std::vector<Dummy>& dummies,
                                                  const CellGrid& grid, const PointCounter& counter,
                                                  int dimension, int subdivisions, int threads) {
  std::vector<std::vector<CellPart>> parts(dummies.size());
  Vec3 cell = Vec3::Zero();
  for (int axis = 0; axis < dimension; ++axis)
    cell[axis] = grid.sizes[axis] / grid.count[static_cast<std::size_t>(axis)];
  on_threads(threads, [&](std::size_t begin, std::size_t step) {
    for (std::size_t d = begin; d < dummies.size(); d += step)
      parts[d] = sampled_cell(counter, dummies[d].element, cell, dimension, subdivisions);
  });
  return parts;
}

}  // namespace

QuadratureDesign quadrature_design(const geometry::Scene& exemplar, const FitOptions& options,
                                   const FitRegion& region, const geometry::PairMeasurer& measurer,
                                   const model::Interaction& interaction,
                                   const ExemplarStatistics& statistics,
                                   const std::vector<std::vector<int>>& shapes_of,
                                   const geometry::Domain& window) {
  const int dimension = region.dimension;
  const int categories = static_cast<int>(shapes_of.size());
  const CellGrid grid(
      region, options.quadrature > 0 ? options.quadrature : default_quadrature_cells(dimension));
  QuadratureDesign out;
  out.cells = grid.cells;
  out.cells_along = grid.cells_along;
  PseudoLikelihoodDesign& design = out.design;
  design.parameter_count = interaction.parameter_count();
  design.data_sum = statistics.data_sum;

  std::vector<std::size_t> block_start;
  const std::vector<Dummy> dummies =
      place_dummies(grid, region, options, measurer, statistics, shapes_of,
                    data_by_cell(exemplar, region, grid, categories), block_start, design);
  out.data_points = design.points.size();
  // A saturated band's statistic reads each neighbour's own count: its cells are sampled.
  const bool saturated = interaction.saturated();
  out.lines = options.lines && interaction.range() > 0 && !saturated;
  const PointCounter counter(exemplar, window.periodic(), measurer, interaction, &statistics);
  std::vector<std::vector<CellPart>> parts =
      saturated ? sample_dummies(dummies, grid, counter, dimension,
                                 saturated_subdivisions(grid, interaction), options.threads)
                : integrate_dummies(dummies, block_start, grid, region, exemplar, options, measurer,
                                    interaction, window, out.lines);

  // Lines: the data points' share comes off every line of their category alike, so that the
  // weights still sum to |W|.
  std::vector<double> line_scale(static_cast<std::size_t>(categories), 1.0);
  if (out.lines) {
    const double measure = grid.sizes.head(dimension).prod();
    for (const QuadraturePoint& q : design.points)
      line_scale[static_cast<std::size_t>(q.category)] -= q.weight / measure;
  }
  for (std::size_t d = 0; d < dummies.size(); ++d) {
    for (CellPart& part : parts[d]) {
      // An anchored category's integral is its own (anchored_quadrature.hpp).
      if (interaction.anchor(dummies[d].element.category) >= 0) continue;
      QuadraturePoint q;
      q.weight = out.lines ? dummies[d].line_weight *
                                 line_scale[static_cast<std::size_t>(dummies[d].element.category)] *
                                 part.fraction
                           : dummies[d].weight * part.fraction;
      q.category = dummies[d].element.category;
      q.counts = std::move(part.counts);
      design.points.push_back(std::move(q));
    }
  }
  for (QuadraturePoint& q : anchored_quadrature(exemplar, region, measurer, interaction, shapes_of,
                                                window, counter, kAnchoredPointsPerBase))
    design.points.push_back(std::move(q));
  return out;
}

PseudoLikelihoodDesign with_data_share(const QuadratureDesign& quadrature, double data_weight,
                                       double factor) {
  PseudoLikelihoodDesign heavier = quadrature.design;
  const double dummy_scale = (1 - factor * data_weight) / (1 - data_weight);
  for (std::size_t i = 0; i < heavier.points.size(); ++i)
    heavier.points[i].weight *= i < quadrature.data_points ? factor : dummy_scale;
  return heavier;
}

void merge_equal_points(PseudoLikelihoodDesign& design) {
  std::map<std::pair<int, std::vector<std::pair<int, int>>>, double> merged;
  for (QuadraturePoint& q : design.points) merged[{q.category, std::move(q.counts)}] += q.weight;
  design.points.clear();
  for (auto& [key, weight] : merged) design.points.push_back({weight, key.first, key.second});
}

}  // namespace shapeproc::fit
