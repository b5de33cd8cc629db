#include "tools/cli/distributed_sample.hpp"

#include <filesystem>
#include <system_error>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/resource_budget.hpp"
#include "libshapeproc/core/stopwatch.hpp"
#include "libshapeproc/io/synthesis_record_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "tools/cli/progress.hpp"
#ifdef SHAPEPROC_WITH_MPI
#include "libshapeproc/distributed/distributed_sampling.hpp"
#include "libshapeproc/distributed/output_parts.hpp"
#endif

namespace shapeproc::cli {

void DistributedFlags::add_to(CLI::App& command) {
  command.add_flag("--distributed", distributed,
                   "sample one output across MPI ranks (run under mpirun): each rank writes its "
                   "part of the .csv, rank 0 a manifest of the parts (docs/sample.md)");
  command.add_flag("--merge", merge,
                   "with --distributed: join the parts into the one .csv that -o names");
}

void DistributedFlags::check(const SampleFlags& sample, const std::string& output) const {
  if (merge && !distributed) throw core::UsageError("--merge is for --distributed runs");
  if (!distributed) return;
#ifndef SHAPEPROC_WITH_MPI
  throw core::UsageError("--distributed: this shapeproc was built without MPI");
#endif
  if (io::extension_of(output) != "csv")
    throw core::UsageError("--distributed writes its output as CSV parts: give -o OUT.csv, got '" +
                           output + "'");
  if (!sample.png.empty())
    throw core::UsageError(
        "--png: a distributed output is not drawn (no rank holds it whole); draw a piece of it "
        "from its CSV");
  if (!sample.trace.empty()) throw core::UsageError("--trace: not written by --distributed runs");
  if (sample.chains != 1) throw core::UsageError("--distributed samples one output: drop --chains");
  if (sample.decompose == "off")
    throw core::UsageError("--distributed samples by cells: drop --decompose off");
}

#ifdef SHAPEPROC_WITH_MPI
namespace {

// Parts and manifest (or the merged output) that exist, refused without --force: the same on
// every rank, so every rank stops alike.
void check_free(const std::vector<std::string>& files, bool force) {
  if (force) return;
  for (const std::string& file : files) {
    std::error_code error;
    if (std::filesystem::exists(file, error))
      throw core::UsageError(file + " exists: give --force to overwrite, or another -o");
  }
}

}  // namespace

int run_distributed(const SampleFlags& sample, const DistributedFlags& flags,
                    const model::ShapeProcessModel& model, const std::string& output,
                    synthesis::SynthesisRecord record, std::ostream& out) {
  const geometry::Domain domain = sample.domain(model.dimension);
  const core::ResourceBudget budget = sample.budget.budget();
  distributed::MpiSession session;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(session.world(), &rank);
  MPI_Comm_size(session.world(), &ranks);
  const distributed::OutputFiles files = distributed::output_files(output, ranks);
  // A merge writes the parts too, before it joins and removes them.
  std::vector<std::string> written = files.parts;
  if (flags.merge)
    written.insert(written.end(), {output, output + ".json"});
  else
    written.push_back(files.manifest);
  check_free(written, sample.force);
  ProgressBar bar("sampling", sample.verbosity.show_progress() && rank == 0);
  synthesis::ChainControl control;
  if (rank == 0)
    control.progress = [&bar](long long done, long long total) { bar.update(done, total); };
  const core::Stopwatch watch;
  distributed::DistributedSample result = distributed::sample_distributed(
      model, domain, sample.output_sampling(), sample.seed, session.world(), budget, control);
  bar.finish();
  // The record `sample` writes, and the ranks.
  record.domain_file = sample.domain_file;
  record.intensity_file = sample.intensity;
  record.take_run(result.result.record);
  record.options.emplace_back("ranks", std::to_string(ranks));
  record.seed = record.chain_seed = sample.seed;
  const std::vector<std::string> left = distributed::write_output(
      result, output, io::synthesis_provenance(record), flags.merge, session.world());
  if (rank != 0) return 0;
  out << "sampled " << result.elements << " elements in " << record.steps << " steps ("
      << watch.seconds() << " s";
  for (const auto& [name, value] : result.result.counters) out << "; " << name << ' ' << value;
  out << "; exchanged " << core::format_bytes(static_cast<double>(result.bytes_sent)) << "), seed "
      << sample.seed << ", across " << ranks << " rank(s)\n";
  if (!record.stationary)
    out << "warning: the element count was still changing after " << record.steps
        << " steps; the output may not be at equilibrium (give --iterations)\n";
  out << "wrote "
      << (flags.merge ? output : std::to_string(ranks) + " part(s) and " + files.manifest) << '\n';
  return 0;
}
#else
int run_distributed(const SampleFlags&, const DistributedFlags&, const model::ShapeProcessModel&,
                    const std::string&, synthesis::SynthesisRecord, std::ostream&) {
  throw core::UsageError("--distributed: this shapeproc was built without MPI");
}
#endif

}  // namespace shapeproc::cli
