#include "libshapeproc/distributed/distributed_sampling.hpp"

#include <memory>
#include <string>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/distributed/mpi_cell_partition.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/sample/output_estimate.hpp"

namespace shapeproc::distributed {

MpiSession::MpiSession() {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (initialised) return;
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw core::ArgumentError("distributed", "MPI could not be started");
  started_ = true;
}

MpiSession::~MpiSession() {
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (started_ && !finalised) MPI_Finalize();
}

core::ResourceEstimate rank_share(const model::ShapeProcessModel& model,
                                  const geometry::Domain& domain, int ranks) {
  core::ResourceEstimate share =
      sample::estimate_output(model, domain, io::recorded_exemplar_density(model), 1);
  share.elements /= ranks;
  share.bytes /= ranks;
  share.basis += ", shared among " + std::to_string(ranks) + " rank(s)";
  return share;
}

DistributedSample sample_distributed(const model::ShapeProcessModel& model,
                                     const geometry::Domain& domain,
                                     const fit::OutputSampling& sampling, std::uint64_t seed,
                                     MPI_Comm communicator, const core::ResourceBudget& budget,
                                     const synthesis::ChainControl& control) {
  auto partition = std::make_shared<MpiCellPartition>(communicator);
  core::check_budget(rank_share(model, domain, partition->processes()), budget,
                     "each rank's share of the output", "{size}");
  // As `sample` samples one output (pipeline::sample_model), its cells spread over the ranks.
  fit::OutputSampling as_sample = sampling;
  as_sample.exemplar_density = io::recorded_exemplar_density(model);
  as_sample.chains_at_once = 1;
  as_sample.compress = true;
  as_sample.decompose = fit::Decomposition::on;
  sample::SamplerOptions options = fit::output_sampler_options(model, domain, as_sample);
  options.partition = partition;
  const sample::ShapeProcessSampler sampler(model, domain, options);
  core::Random random(seed);
  DistributedSample out;
  out.result = sampler.describe(sampler.sample(random, control));
  out.rank = partition->rank();
  out.ranks = partition->processes();
  out.elements = partition->sum(static_cast<long long>(out.result.scene.elements.size()));
  out.bytes_sent = partition->sum(partition->bytes_sent());
  return out;
}

}  // namespace shapeproc::distributed
