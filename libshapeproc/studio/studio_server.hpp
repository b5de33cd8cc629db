// The studio's local web server (cpp-httplib): the page, and a small JSON interface over a
// StudioSession. Every request must carry the session's token (in the X-Studio-Token header, or
// ?token= for the page itself) and, on a loopback address, name that address as its Host (a page
// elsewhere cannot reach it by DNS rebinding). Request bodies are bounded; a refused request gets
// a status and {"error": "..."} and changes nothing.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "libshapeproc/studio/studio_session.hpp"

namespace shapeproc::studio {

struct ServerOptions {
  std::string host = "127.0.0.1";
  int port = 0;       // 0: any free port
  std::string token;  // empty: 128 random bits, in hex
  std::size_t max_body = 16 * 1024;
  // The longest a request for the next preview waits before answering "none yet".
  int preview_wait_ms = 15'000;
};

class StudioServer {
 public:
  // Binds the address; throws core::UsageError when it cannot (the port taken, no such host).
  StudioServer(StudioSession& session, ServerOptions options);
  ~StudioServer();
  StudioServer(const StudioServer&) = delete;
  StudioServer& operator=(const StudioServer&) = delete;

  int port() const;
  const std::string& token() const;
  // The page's address, token included: http://127.0.0.1:PORT/?token=...
  std::string url() const;
  // Serves until stop() (from another thread or a signal's watcher).
  void run();
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The page (HTML with its CSS and JavaScript inlined), built into the library.
const std::string& studio_page();

}  // namespace shapeproc::studio
