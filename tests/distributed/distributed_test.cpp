// The distributed sampler, run by ctest under `mpirun -n 1`, `-n 2` and `-n 3`: every rank runs
// every test, and a test fails if it fails on any rank.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/distributed/distributed_sampling.hpp"
#include "libshapeproc/distributed/mpi_cell_partition.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/sample/cell_layout.hpp"
#include "tests/squares_model.hpp"

namespace shapeproc::distributed {
namespace {

using geometry::Vec3;

int ranks() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

// The cells of an 80 × 60 torus cut at 10: 8 × 6.
std::optional<sample::CellLayout> eight_by_six() {
  return sample::CellLayout::plan(geometry::Domain::from_sizes({80, 60}, geometry::Boundary::torus),
                                  10.0);
}

// A 2D torus of 8 × 6 cells: rows run across y (the outermost cut axis); each rank owns a run of
// whole rows, the runs in rank order cover the cell numbers once, in order.
TEST(MpiCellPartition, RanksOwnRunsOfWholeRowsInCellOrder) {
  const std::optional<sample::CellLayout> layout = eight_by_six();
  ASSERT_TRUE(layout);
  MpiCellPartition partition(MPI_COMM_WORLD);
  partition.plan(*layout);
  EXPECT_EQ(partition.axis(), 1);
  EXPECT_EQ(partition.rows(), 6);
  int previous = 0;
  for (int c = 0; c < layout->count(); ++c) {
    const int owner = partition.owner(c);
    EXPECT_TRUE(owner == previous || owner == previous + 1) << "cell " << c;
    EXPECT_EQ(owner, partition.owner(c - c % 8)) << "a row has one owner";
    previous = owner;
  }
  EXPECT_EQ(previous, ranks() - 1);
}

// After refresh_borders, every cell around a rank's own holds what its owner holds; cells nobody
// around reads stay as they were.
TEST(MpiCellPartition, BordersArriveFromTheirOwners) {
  const std::optional<sample::CellLayout> layout = eight_by_six();
  ASSERT_TRUE(layout);
  MpiCellPartition partition(MPI_COMM_WORLD);
  partition.plan(*layout);
  // Cell c holds c % 5 + 1 elements, each naming its cell, as its owner sees it.
  const auto filled = [](int c) {
    std::vector<geometry::Element> list(static_cast<std::size_t>(c % 5 + 1));
    for (std::size_t k = 0; k < list.size(); ++k)
      list[k] = {c, static_cast<int>(k), Vec3(c, 0.5 * static_cast<double>(k), 0)};
    return list;
  };
  std::vector<std::vector<geometry::Element>> cells(static_cast<std::size_t>(layout->count()));
  for (int c = 0; c < layout->count(); ++c)
    if (partition.owns(c)) cells[static_cast<std::size_t>(c)] = filled(c);
  partition.refresh_borders(cells);
  for (int c = 0; c < layout->count(); ++c) {
    if (!partition.owns(c)) continue;
    for (int other : layout->around(c)) {
      const auto expected = filled(other);
      const auto& got = cells[static_cast<std::size_t>(other)];
      ASSERT_EQ(got.size(), expected.size()) << "cell " << other;
      for (std::size_t k = 0; k < got.size(); ++k) {
        EXPECT_EQ(got[k].shape, expected[k].shape);
        EXPECT_EQ(got[k].category, expected[k].category);
        EXPECT_EQ(got[k].position, expected[k].position);
      }
    }
  }
  EXPECT_EQ(partition.sum(partition.rank() + 1), ranks() * (ranks() + 1) / 2);
  EXPECT_TRUE(partition.any(partition.rank() == ranks() - 1));
  EXPECT_FALSE(partition.any(false));
}

// The squares model on a 240 × 180 torus: each rank's part is its slice of the output one process
// samples with the same seed, element for element, and the parts add up to it.
TEST(DistributedSampling, EachRankHoldsItsSliceOfTheOneProcessOutput) {
  const model::ShapeProcessModel model = io::parse_model(testing::kSquaresModel, "squares");
  const geometry::Domain torus =
      geometry::Domain::from_sizes({240, 180}, geometry::Boundary::torus);
  fit::OutputSampling sampling;
  sampling.decompose = fit::Decomposition::on;
  sampling.threads = 1;
  const DistributedSample part = sample_distributed(model, torus, sampling, 7, MPI_COMM_WORLD);
  // The same output from one process, on every rank.
  fit::OutputSampling alone = sampling;
  alone.exemplar_density = io::recorded_exemplar_density(model);
  const sample::ShapeProcessSampler sampler(model, torus,
                                            fit::output_sampler_options(model, torus, alone));
  core::Random random(7);
  const std::vector<geometry::Element> whole = sampler.sample(random).scene.elements;
  ASSERT_EQ(part.elements, static_cast<long long>(whole.size()));
  ASSERT_GT(whole.size(), 100u);
  long long mine = static_cast<long long>(part.result.scene.elements.size()), before = 0;
  MPI_Exscan(&mine, &before, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  if (part.rank == 0) before = 0;
  for (std::size_t k = 0; k < part.result.scene.elements.size(); ++k) {
    const geometry::Element& e = part.result.scene.elements[k];
    const geometry::Element& w = whole[static_cast<std::size_t>(before) + k];
    ASSERT_EQ(e.position, w.position) << "rank " << part.rank << ", element " << k;
    ASSERT_EQ(e.shape, w.shape);
    ASSERT_EQ(e.category, w.category);
  }
}

// What the decomposed sampler cannot take is refused on every rank alike, before any exchange:
// a domain too small for cells of the model's reach, and a model whose outputs need the
// compressing burn-in (a packed exemplar's fit).
TEST(DistributedSampling, RefusesWhatItCannotDecompose) {
  model::ShapeProcessModel model = io::parse_model(testing::kSquaresModel, "squares");
  fit::OutputSampling sampling;
  sampling.threads = 1;
  const geometry::Domain tiny = geometry::Domain::from_sizes({12, 12}, geometry::Boundary::torus);
  EXPECT_THROW(sample_distributed(model, tiny, sampling, 1, MPI_COMM_WORLD), core::ArgumentError);
  model.fit.emplace();
  model.fit->likelihood.emplace();
  model.fit->likelihood->burn_in_kind = model::BurnIn::compressing;
  const geometry::Domain torus =
      geometry::Domain::from_sizes({240, 180}, geometry::Boundary::torus);
  EXPECT_THROW(sample_distributed(model, torus, sampling, 1, MPI_COMM_WORLD), core::ArgumentError);
}

}  // namespace
}  // namespace shapeproc::distributed

int main(int argc, char** argv) {
  const shapeproc::distributed::MpiSession session;
  ::testing::InitGoogleTest(&argc, argv);
  // Only rank 0 reports; every rank's result counts.
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  int failed = RUN_ALL_TESTS(), any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return any;
}
