#include "libshapeproc/studio/studio_server.hpp"

#include <gtest/gtest.h>
#include <httplib.h>

#include <thread>

#include "libshapeproc/io/model_io.hpp"
#include "tests/squares_model.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::studio {
namespace {

// A studio on the squares model, served on a free port for the test's requests.
class StudioServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    StudioInput input;
    input.model = io::parse_model(testing::kSquaresModel, "squares.json");
    input.source = "squares.json";
    input.preview_size = {30, 30};
    input.full_size = {40, 40};
    input.export_directory = dir_.path();
    session_ = std::make_unique<StudioSession>(std::move(input));
    server_ = std::make_unique<StudioServer>(*session_, ServerOptions{});
    thread_ = std::thread([this] { server_->run(); });
  }
  void TearDown() override {
    server_->stop();
    thread_.join();
  }

  httplib::Client client() const {
    httplib::Client c("127.0.0.1", server_->port());
    c.set_read_timeout(30, 0);
    return c;
  }
  httplib::Headers token() const { return {{"X-Studio-Token", server_->token()}}; }
  httplib::Result edit(const std::string& body) const {
    return client().Post("/api/edit", token(), body, "application/json");
  }

  testing::TempDir dir_;
  std::unique_ptr<StudioSession> session_;
  std::unique_ptr<StudioServer> server_;
  std::thread thread_;
};

TEST_F(StudioServerTest, ServesThePageAndTheStateWithTheToken) {
  const auto page = client().Get("/?token=" + server_->token());
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("shapeproc studio"), std::string::npos);
  EXPECT_NE(page->body.find("pollPreviews"), std::string::npos);  // the script is inlined
  const auto state = client().Get("/api/state", token());
  ASSERT_TRUE(state);
  EXPECT_EQ(state->status, 200);
  EXPECT_NE(state->body.find("\"phase\":\"ready\""), std::string::npos);
  const auto accepted = edit(R"({"kind":"gamma","pair":0,"axis":0,"index":0,"value":2})");
  ASSERT_TRUE(accepted);
  EXPECT_EQ(accepted->status, 200) << accepted->body;
  EXPECT_EQ(session_->state().revision, 2);
  EXPECT_EQ(server_->url(),
            "http://127.0.0.1:" + std::to_string(server_->port()) + "/?token=" + server_->token());
}

TEST_F(StudioServerTest, RefusesRequestsWithoutTheTokenOrFromAnotherHost) {
  const auto none = client().Get("/api/state");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->status, 403);
  EXPECT_NE(none->body.find("no token"), std::string::npos);
  const auto wrong = client().Get("/?token=0123");
  ASSERT_TRUE(wrong);
  EXPECT_EQ(wrong->status, 403);
  EXPECT_NE(wrong->body.find("wrong token"), std::string::npos);
  httplib::Headers rebound = token();
  rebound.emplace("Host", "evil.example:80");
  const auto host = client().Get("/api/state", rebound);
  ASSERT_TRUE(host);
  EXPECT_EQ(host->status, 403);
  EXPECT_NE(host->body.find("wrong host"), std::string::npos);
  const auto posted = client().Post(
      "/api/edit", R"({"kind":"gamma","pair":0,"axis":0,"index":0,"value":2})", "application/json");
  ASSERT_TRUE(posted);
  EXPECT_EQ(posted->status, 403);
  EXPECT_EQ(session_->state().revision, 1);  // nothing changed
}

TEST_F(StudioServerTest, MalformedEditsGetAClearErrorAndChangeNothing) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"kind":"gamma","pair":0,"axis":0,"index":0,"value":NaN})", "JSON object"},
      {R"({"kind":"gamma","pair":0,"axis":0,"index":0,"value":"high"})", "finite number"},
      {R"({"kind":"gamma","pair":0,"axis":0,"index":0,"value":1e999})", ""},  // inf, or refused
      {R"({"kind":"gamma","pair":0,"axis":0,"index":0,"value":-1})", "negative"},
      {R"({"kind":"gamma","pair":7,"axis":0,"index":0,"value":1})", "no interaction 7"},
      {R"({"kind":"gamma","pair":-1,"axis":0,"index":0,"value":1})", "whole number"},
      {R"({"kind":"gamma","pair":0,"axis":0,"index":9,"value":1})", "no band 10"},
      {R"({"kind":"threshold","pair":0,"axis":0,"index":0,"value":100})", "invalid"},
      {R"({"kind":"teleport"})", "unknown kind"},
      {R"({"pair":0})", "'kind' is missing"},
      {"[1,2,3]", "JSON object"},
      {"", "JSON object"},
  };
  for (const auto& [body, message] : cases) {
    const auto answer = edit(body);
    ASSERT_TRUE(answer) << body;
    EXPECT_EQ(answer->status, 400) << body;
    EXPECT_NE(answer->body.find(message), std::string::npos) << body << " -> " << answer->body;
  }
  const auto seed = client().Post("/api/seed", token(), R"({"seed":-3})", "application/json");
  ASSERT_TRUE(seed);
  EXPECT_EQ(seed->status, 400);
  const auto name =
      client().Post("/api/export", token(), R"({"name":"../../etc/x"})", "application/json");
  ASSERT_TRUE(name);
  EXPECT_EQ(name->status, 400);
  const auto big = edit(std::string(64 * 1024, ' '));
  ASSERT_TRUE(big);
  EXPECT_EQ(big->status, 413);
  EXPECT_NE(big->body.find("too large"), std::string::npos);
  EXPECT_EQ(session_->state().revision, 1);
  EXPECT_TRUE(std::filesystem::is_empty(dir_.path()));  // nothing written
}

}  // namespace
}  // namespace shapeproc::studio
