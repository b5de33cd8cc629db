#include "libshapeproc/core/interruption.hpp"

#include <unistd.h>

#include <array>
#include <csignal>
#include <cstring>

namespace shapeproc::core {

namespace {

// Everything the handler touches is lock-free atomics or plain memory published through them.
std::atomic<bool> interrupted{false};
std::atomic<int> sections{0};
std::atomic<int> signals_seen{0};

constexpr int kSlots = 16;
constexpr std::size_t kPathBytes = 4096;
enum Slot : int { kFree = 0, kClaimed = 1, kReady = 2 };
std::array<std::atomic<int>, kSlots> slot_state{};
std::array<std::array<char, kPathBytes>, kSlots> slot_path{};

extern "C" void on_signal(int signal_number) {
  const int seen = signals_seen.fetch_add(1) + 1;
  interrupted.store(true);
  if (sections.load() > 0 && seen == 1) return;  // the section's run stops by itself
  for (int s = 0; s < kSlots; ++s) {
    if (slot_state[static_cast<std::size_t>(s)].load() == kReady)
      unlink(slot_path[static_cast<std::size_t>(s)].data());
  }
  static const char message[] = "shapeproc: interrupted; nothing was written\n";
  const ssize_t ignored = write(STDERR_FILENO, message, sizeof message - 1);
  (void)ignored;
  _exit(128 + signal_number);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

CancellableSection::CancellableSection() {
  interrupted.store(false);
  signals_seen.store(0);
  sections.fetch_add(1);
}

CancellableSection::~CancellableSection() { sections.fetch_sub(1); }

const std::atomic<bool>* CancellableSection::flag() { return &interrupted; }

TemporaryFileMark::TemporaryFileMark(const std::string& path) {
  if (path.size() >= kPathBytes) return;
  for (int s = 0; s < kSlots; ++s) {
    int expected = kFree;
    if (slot_state[static_cast<std::size_t>(s)].compare_exchange_strong(expected, kClaimed)) {
      std::memcpy(slot_path[static_cast<std::size_t>(s)].data(), path.c_str(), path.size() + 1);
      slot_state[static_cast<std::size_t>(s)].store(kReady);
      slot_ = s;
      return;
    }
  }
}

TemporaryFileMark::~TemporaryFileMark() {
  if (slot_ >= 0) slot_state[static_cast<std::size_t>(slot_)].store(kFree);
}

}  // namespace shapeproc::core
