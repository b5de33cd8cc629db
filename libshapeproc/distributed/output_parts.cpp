#include "libshapeproc/distributed/output_parts.hpp"

#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/error.hpp"

namespace shapeproc::distributed {

namespace {

// Runs `write` on this rank; if it fails on any rank, every rank throws (this one with its own
// message, the others naming the rank), so that no rank waits for one that gave up.
template <class Write>
void on_every_rank(MPI_Comm communicator, const std::string& file, Write&& write) {
  std::string failure;
  try {
    write();
  } catch (const std::exception& error) {
    failure = error.what();
  }
  int rank = 0, first = 0;
  MPI_Comm_rank(communicator, &rank);
  // The lowest failing rank, if any.
  int mine = failure.empty() ? std::numeric_limits<int>::max() : rank;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, communicator);
  if (first == std::numeric_limits<int>::max()) return;
  if (!failure.empty()) throw core::InputError(file, 0, failure);
  throw core::InputError(file, 0, "rank " + std::to_string(first) + " could not write its part");
}

}  // namespace

OutputFiles output_files(const std::string& output, int ranks) {
  const std::filesystem::path path(output);
  const std::filesystem::path stem = path.parent_path() / path.stem();
  OutputFiles files;
  for (int r = 0; r < ranks; ++r)
    files.parts.push_back(stem.string() + "-part-" + std::to_string(r + 1) + "-of-" +
                          std::to_string(ranks) + ".csv");
  files.manifest = stem.string() + ".parts.json";
  return files;
}

std::vector<std::string> write_output(const DistributedSample& sample, const std::string& output,
                                      const io::Provenance& provenance, bool merge,
                                      MPI_Comm communicator) {
  const OutputFiles files = output_files(output, sample.ranks);
  const std::string& part = files.parts[static_cast<std::size_t>(sample.rank)];
  on_every_rank(communicator, part, [&] {
    core::write_file_atomically(
        part, [&](std::ostream& out) { io::write_csv(sample.result.scene, out); });
  });
  long long mine = static_cast<long long>(sample.result.scene.elements.size());
  std::vector<long long> counts(static_cast<std::size_t>(sample.ranks));
  MPI_Gather(&mine, 1, MPI_LONG_LONG, counts.data(), 1, MPI_LONG_LONG, 0, communicator);
  const std::string& written = merge ? output : files.manifest;
  on_every_rank(communicator, written, [&] {
    if (sample.rank != 0) return;
    if (!merge) {
      nlohmann::json manifest;
      manifest["format"] = "shapeproc placements in parts";
      manifest["elements"] = sample.elements;
      manifest["record"] = provenance.json.empty() ? nlohmann::json::object()
                                                   : nlohmann::json::parse(provenance.json);
      for (std::size_t r = 0; r < files.parts.size(); ++r)
        manifest["parts"].push_back(
            {{"file", std::filesystem::path(files.parts[r]).filename().string()},
             {"elements", counts[r]}});
      core::write_file_atomically(files.manifest,
                                  [&](std::ostream& out) { out << manifest.dump(2) << '\n'; });
      return;
    }
    // The parts in rank order are the cells in order: one header, then every part's rows.
    core::write_file_atomically(output, [&](std::ostream& out) {
      for (std::size_t r = 0; r < files.parts.size(); ++r) {
        std::ifstream in(files.parts[r], std::ios::binary);
        std::string header;
        if (!std::getline(in, header)) throw core::InputError(files.parts[r], 0, "empty part");
        if (r == 0) out << header << '\n';
        if (in.peek() != std::ifstream::traits_type::eof()) out << in.rdbuf();
      }
    });
    if (!provenance.json.empty())
      core::write_file_atomically(output + ".json",
                                  [&](std::ostream& out) { out << provenance.json << '\n'; });
  });
  if (!merge) {
    std::vector<std::string> left = files.parts;
    left.push_back(files.manifest);
    return left;
  }
  MPI_Barrier(communicator);  // every rank past the merge before its part goes
  std::error_code ignored;
  std::filesystem::remove(part, ignored);
  std::vector<std::string> left{output};
  if (!provenance.json.empty()) left.push_back(output + ".json");
  return left;
}

}  // namespace shapeproc::distributed
