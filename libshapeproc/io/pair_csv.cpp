#include "libshapeproc/io/pair_csv.hpp"

#include "libshapeproc/core/atomic_file.hpp"
#include "libshapeproc/core/format.hpp"

namespace shapeproc::io {

void write_pairs_csv(std::ostream& out, int dimension,
                     const std::vector<geometry::PairRecord>& pairs) {
  out << (dimension == 3 ? "i,j,distance,ox,oy,oz,axis\n" : "i,j,distance,ox,oy,axis\n");
  for (const geometry::PairRecord& p : pairs) {
    const geometry::Measurement& m = p.measurement;
    out << p.i << ',' << p.j << ',' << core::format_number(m.distance) << ','
        << core::format_number(m.direction.x()) << ',' << core::format_number(m.direction.y())
        << ',';
    if (dimension == 3) out << core::format_number(m.direction.z()) << ',';
    out << m.axis << '\n';
  }
}

void write_pairs_csv(const std::filesystem::path& file, int dimension,
                     const std::vector<geometry::PairRecord>& pairs, const Provenance& provenance) {
  core::write_file_atomically(file,
                              [&](std::ostream& out) { write_pairs_csv(out, dimension, pairs); });
  std::filesystem::path sidecar = file;
  sidecar += ".json";
  core::write_file_atomically(sidecar, [&](std::ostream& out) { out << provenance.json << '\n'; });
}

}  // namespace shapeproc::io
