#include "libshapeproc/core/atomic_file.hpp"

#include <fstream>
#include <random>
#include <stdexcept>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/interruption.hpp"

namespace shapeproc::core {

namespace fs = std::filesystem;

namespace {

// Creates the target's directory, refuses a target that is a directory, and returns a name beside
// it for a temporary file, unique enough for concurrent writers of the same target.
fs::path temporary_beside(const fs::path& target) {
  std::error_code ec;
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
  if (fs::is_directory(target, ec)) {
    throw UsageError(target.string() + ": output is a directory, not a file");
  }
  std::random_device entropy;
  return fs::path(target.string() + ".tmp-" + std::to_string(entropy() % 1000000000u));
}

}  // namespace

void check_writable(const fs::path& target) {
  const fs::path probe = temporary_beside(target);
  const bool created = static_cast<bool>(std::ofstream(probe, std::ios::binary));
  std::error_code ec;
  fs::remove(probe, ec);
  if (!created) throw UsageError(target.string() + ": cannot create the output file");
}

void write_file_atomically(const fs::path& target,
                           const std::function<void(std::ostream&)>& write) {
  const fs::path temporary = temporary_beside(target);
  const TemporaryFileMark mark(temporary.string());  // removed if a signal ends the process
  try {
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out) throw UsageError(target.string() + ": cannot create the output file");
      write(out);
      out.flush();
      if (!out) throw std::runtime_error(target.string() + ": write failed");
    }
    fs::rename(temporary, target);
  } catch (...) {
    std::error_code ec;
    fs::remove(temporary, ec);
    throw;
  }
}

}  // namespace shapeproc::core
