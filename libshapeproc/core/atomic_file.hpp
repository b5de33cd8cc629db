// Writing outputs so that nothing half-written is ever left behind.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace shapeproc::core {

// Calls `write` with a stream on a temporary file beside `target`, then renames it to `target`.
// If `write` throws or the stream fails, the temporary file is removed, `target` is left as it
// was and the exception propagates. Missing parent directories are created.
void write_file_atomically(const std::filesystem::path& target,
                           const std::function<void(std::ostream&)>& write);

// Checks before any long work that `target` can be written: its directory exists or can be
// created, and a file can be created in it (then removed). Throws UsageError otherwise, so that a
// run with several outputs does not write the first and fail on the second.
void check_writable(const std::filesystem::path& target);

}  // namespace shapeproc::core
