// Ctrl-C (SIGINT) and SIGTERM during a run: it stops without leaving a temporary file behind.
// While a CancellableSection is alive (a run that polls its flag, such as the sampler's chains),
// the first signal only sets the flag: the run stops at its next check and writes nothing. With no
// such section, and at a second signal, the process removes the temporary files being written
// (write_file_atomically marks them) and exits at once with 128 + the signal's number.
#pragma once

#include <atomic>
#include <string>

namespace shapeproc::core {

// Installs the handlers for the whole process (the command line's main does, once).
void install_interrupt_handlers();

class CancellableSection {
 public:
  CancellableSection();
  ~CancellableSection();
  CancellableSection(const CancellableSection&) = delete;
  CancellableSection& operator=(const CancellableSection&) = delete;
  // Set by the first signal while a section is alive; the same flag for every section, so a
  // run may take it before the section that guards its chains begins.
  static const std::atomic<bool>* flag();
};

// Marks `path` as a temporary file being written while alive, for the handler to remove.
class TemporaryFileMark {
 public:
  explicit TemporaryFileMark(const std::string& path);
  ~TemporaryFileMark();
  TemporaryFileMark(const TemporaryFileMark&) = delete;
  TemporaryFileMark& operator=(const TemporaryFileMark&) = delete;

 private:
  int slot_ = -1;  // -1: no slot was free (the file is still removed on errors, not on signals)
};

}  // namespace shapeproc::core
