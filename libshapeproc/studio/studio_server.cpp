#include "libshapeproc/studio/studio_server.hpp"

#include <httplib.h>

#include <chrono>
#include <random>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/studio/detail/studio_json.hpp"

namespace shapeproc::studio {

namespace {

std::string random_token() {
  std::random_device device;
  std::string token;
  for (int k = 0; k < 4; ++k) {
    char part[9];
    std::snprintf(part, sizeof part, "%08x", static_cast<unsigned>(device()));
    token += part;
  }
  return token;
}

// Compares in time independent of where the strings first differ.
bool same_token(const std::string& given, const std::string& token) {
  if (given.size() != token.size()) return false;
  unsigned char differ = 0;
  for (std::size_t k = 0; k < token.size(); ++k)
    differ |= static_cast<unsigned char>(given[k] ^ token[k]);
  return differ == 0;
}

bool loopback(const std::string& host) {
  return host == "127.0.0.1" || host == "localhost" || host == "::1";
}

void refuse(httplib::Response& response, int status, const std::string& message) {
  response.status = status;
  response.set_content(detail::error_json(message), "application/json");
}

void answer(httplib::Response& response, const std::string& json) {
  response.set_header("Cache-Control", "no-store");
  response.set_content(json, "application/json");
}

}  // namespace

struct StudioServer::Impl {
  StudioSession& session;
  ServerOptions options;
  httplib::Server server;
  int port = 0;

  Impl(StudioSession& s, ServerOptions o) : session(s), options(std::move(o)) {}

  // The token and the Host header, before any route.
  httplib::Server::HandlerResponse admit(const httplib::Request& request,
                                         httplib::Response& response) const {
    if (loopback(options.host)) {
      const std::string host = request.get_header_value("Host");
      const std::string port_part = ":" + std::to_string(port);
      const bool named = host == "127.0.0.1" + port_part || host == "localhost" + port_part ||
                         host == "[::1]" + port_part;
      if (!named) {
        refuse(response, 403,
               "wrong host '" + host + "': the studio answers only to " + options.host + port_part);
        return httplib::Server::HandlerResponse::Handled;
      }
    }
    const std::string given = request.has_header("X-Studio-Token")
                                  ? request.get_header_value("X-Studio-Token")
                                  : request.get_param_value("token");
    if (!same_token(given, options.token)) {
      refuse(response, 403,
             given.empty() ? "no token: open the address the studio printed, token included"
                           : "wrong token");
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  }

  // A POST route: `act` parses the body and acts on the session, returning the answer's JSON;
  // its errors become 400 (a request the model or the parser refuses) or 409 (the model is not
  // ready).
  template <class Act>
  void post(const char* path, Act act) {
    server.Post(path, [this, act](const httplib::Request& request, httplib::Response& response) {
      try {
        answer(response, act(request.body));
      } catch (const core::UsageError& e) {
        refuse(response, 409, e.what());
      } catch (const std::invalid_argument& e) {
        refuse(response, 400, e.what());
      } catch (const std::exception& e) {
        refuse(response, 500, e.what());
      }
    });
  }

  void routes();
};

void StudioServer::Impl::routes() {
  server.set_pre_routing_handler(
      [this](const httplib::Request& request, httplib::Response& response) {
        return admit(request, response);
      });
  server.set_error_handler([](const httplib::Request&, httplib::Response& response) {
    if (!response.body.empty()) return;
    const char* what = response.status == 413   ? "the request body is too large"
                       : response.status == 404 ? "no such address"
                                                : "the request was refused";
    refuse(response, response.status, what);
  });
  server.Get("/", [](const httplib::Request&, httplib::Response& response) {
    response.set_header("Cache-Control", "no-store");
    response.set_content(studio_page(), "text/html; charset=utf-8");
  });
  server.Get("/api/state", [this](const httplib::Request&, httplib::Response& response) {
    answer(response, detail::state_json(session.state()));
  });
  server.Get("/api/exemplar.svg", [this](const httplib::Request&, httplib::Response& response) {
    response.set_content(session.exemplar_svg(), "image/svg+xml");
  });
  server.Get("/api/preview", [this](const httplib::Request& request, httplib::Response& response) {
    long long after = 0;
    const std::string text = request.get_param_value("after");
    if (!text.empty()) {
      try {
        after = std::stoll(text);
      } catch (const std::exception&) {
        refuse(response, 400, "preview: 'after' must be a whole number");
        return;
      }
    }
    const auto preview =
        session.wait_preview(after, std::chrono::milliseconds(options.preview_wait_ms));
    if (!preview) {
      response.status = 204;  // none yet: ask again
      return;
    }
    answer(response, detail::preview_json(*preview));
  });
  const auto state = [this] { return detail::state_json(session.state()); };
  post("/api/edit", [this, state](const std::string& body) {
    session.edit(detail::parse_edit(body));
    return state();
  });
  post("/api/undo", [this, state](const std::string&) {
    session.undo();
    return state();
  });
  post("/api/redo", [this, state](const std::string&) {
    session.redo();
    return state();
  });
  post("/api/reset", [this, state](const std::string&) {
    session.reset();
    return state();
  });
  post("/api/seed", [this, state](const std::string& body) {
    const detail::SeedRequest seed = detail::parse_seed(body);
    if (seed.reroll)
      session.reroll_seed();
    else
      session.set_seed(seed.seed);
    return state();
  });
  post("/api/size", [this, state](const std::string& body) {
    session.set_full_size(detail::parse_full(body));
    return state();
  });
  post("/api/export", [this](const std::string& body) {
    const detail::ExportRequest request = detail::parse_export(body);
    return detail::export_json(session.export_preview(request.name, request.overwrite));
  });
}

StudioServer::StudioServer(StudioSession& session, ServerOptions options)
    : impl_(std::make_unique<Impl>(session, std::move(options))) {
  Impl& s = *impl_;
  if (s.options.token.empty()) s.options.token = random_token();
  s.server.set_payload_max_length(s.options.max_body);
  s.routes();
  if (s.options.port == 0) {
    s.port = s.server.bind_to_any_port(s.options.host);
  } else {
    s.port = s.server.bind_to_port(s.options.host, s.options.port) ? s.options.port : -1;
  }
  if (s.port <= 0)
    throw core::UsageError("cannot listen on " + s.options.host + ":" +
                           std::to_string(s.options.port) +
                           ": the port is taken or the address is not this machine's");
}

StudioServer::~StudioServer() { stop(); }

int StudioServer::port() const { return impl_->port; }
const std::string& StudioServer::token() const { return impl_->options.token; }

std::string StudioServer::url() const {
  const std::string& host = impl_->options.host;
  const std::string shown = host == "::1" ? "[::1]" : host;
  return "http://" + shown + ":" + std::to_string(impl_->port) + "/?token=" + impl_->options.token;
}

void StudioServer::run() { impl_->server.listen_after_bind(); }

void StudioServer::stop() { impl_->server.stop(); }

}  // namespace shapeproc::studio
