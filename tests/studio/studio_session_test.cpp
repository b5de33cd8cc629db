#include "libshapeproc/studio/studio_session.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_writers.hpp"
#include "libshapeproc/studio/preview_chain.hpp"
#include "tests/squares_model.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::studio {
namespace {

using namespace std::chrono_literals;

StudioInput squares_input(const std::filesystem::path& exports) {
  StudioInput input;
  input.model = io::parse_model(testing::kSquaresModel, "squares.json");
  input.source = "squares.json";
  input.arguments = {"shapeproc", "studio", "squares.json"};
  input.preview_size = {40, 40};
  input.full_size = {60, 60};
  input.seed = 7;
  input.export_directory = exports;
  return input;
}

// Pictures until the final one of `revision`; every one seen is appended to `seen`.
Preview final_of(const StudioSession& session, long long revision, std::vector<Preview>& seen) {
  long long after = seen.empty() ? 0 : seen.back().sequence;
  for (int wait = 0; wait < 600; ++wait) {
    const std::optional<Preview> p = session.wait_preview(after, 1000ms);
    if (!p) continue;
    seen.push_back(*p);
    after = p->sequence;
    if (p->revision == revision && p->stage == PreviewStage::final) return *p;
  }
  ADD_FAILURE() << "no final preview of revision " << revision;
  return {};
}

std::string svg_of(const geometry::Scene& scene) {
  std::ostringstream svg;
  io::write_svg(scene, svg, {});
  return svg.str();
}

TEST(StudioSession, PreviewsAreWhatSampleMakesAndEditsDraftFirst) {
  const testing::TempDir dir;
  StudioSession session(squares_input(dir.path()));
  std::vector<Preview> seen;
  const Preview first = final_of(session, 1, seen);
  const model::ShapeProcessModel fitted = io::parse_model(testing::kSquaresModel, "squares.json");
  EXPECT_EQ(first.svg, svg_of(sample_output(fitted, {{40, 40}, 7}, {}, nullptr).scene));
  EXPECT_GT(first.elements, 0);
  EXPECT_TRUE(first.verdicts.empty());  // no exemplar, no verdicts

  session.edit({EditKind::gamma, 0, 0, 0, true, 3.0});
  const StudioState state = session.state();
  EXPECT_EQ(state.revision, 2);
  EXPECT_EQ(state.edits, (std::vector<std::string>{"gamma 0:*:1=3"}));
  const std::size_t before = seen.size();
  const Preview second = final_of(session, 2, seen);
  // The edit's first picture is a draft continued from the one on screen.
  ASSERT_GT(seen.size(), before + 1);
  EXPECT_EQ(seen[before].stage, PreviewStage::draft);
  EXPECT_EQ(seen[before].revision, 2);
  model::ShapeProcessModel edited = fitted;
  for (auto& axis : edited.interactions[0].axes) axis.gammas[0] = 3.0;
  EXPECT_EQ(second.svg, svg_of(sample_output(edited, {{40, 40}, 7}, {}, nullptr).scene));
  EXPECT_NE(second.svg, first.svg);

  session.reroll_seed();
  const Preview rerolled = final_of(session, 3, seen);
  EXPECT_NE(rerolled.seed, 7u);
  session.set_full_size(true);
  const Preview full = final_of(session, 4, seen);
  EXPECT_EQ(full.size, (std::vector<double>{60, 60}));
}

TEST(StudioSession, ExportsTheModelTheOutputAndItsCommand) {
  const testing::TempDir dir;
  StudioSession session(squares_input(dir.path()));
  session.edit({EditKind::gamma, 0, 1, 0, false, 2.0});
  const ExportResult result = session.export_preview("pattern", false);
  ASSERT_EQ(result.files.size(), 4u);
  for (const auto& file : result.files) EXPECT_TRUE(std::filesystem::exists(file)) << file;
  EXPECT_EQ(result.command, "shapeproc sample pattern.json -o pattern.svg --size 40,40 --seed 7");
  const model::ShapeProcessModel exported = io::read_model(dir.file("pattern.json"));
  EXPECT_EQ(exported.interactions[0].axes[1].gammas[0], 2.0);
  ASSERT_TRUE(exported.fit);
  EXPECT_EQ(exported.fit->edits.back().edits, (std::vector<std::string>{"gamma 0:1:1=2"}));
  EXPECT_NE(testing::read_file(dir.file("pattern.sh")).find(result.command), std::string::npos);
  // The exported model, read back as `sample` reads it, makes the exported output again.
  const std::string written = testing::read_file(dir.file("pattern.svg"));
  const std::string body = written.substr(written.find("</metadata>") + 11);
  EXPECT_EQ(svg_of(sample_output(exported, {{40, 40}, 7}, {}, nullptr).scene),
            written.substr(0, written.find("<metadata")) + body.substr(1));
  // Files that exist are kept unless told; a name that is no plain name writes nothing.
  EXPECT_THROW(session.export_preview("pattern", false), core::ArgumentError);
  EXPECT_NO_THROW(session.export_preview("pattern", true));
  for (const char* name : {"../escape", "", "a/b", "x.json"})
    EXPECT_THROW(session.export_preview(name, false), core::ArgumentError) << name;
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            4);
}

TEST(StudioSession, AFinalChainOverTheTimeLimitIsCutShortAndTheExportSamplesItInFull) {
  const testing::TempDir dir;
  StudioInput input = squares_input(dir.path());
  input.final_seconds = 1e-9;  // every final chain is over it at its first check
  StudioSession session(input);
  std::optional<Preview> cut;
  long long after = 0;
  for (int wait = 0; wait < 600 && !cut; ++wait) {
    const std::optional<Preview> p = session.wait_preview(after, 1000ms);
    if (!p) continue;
    after = p->sequence;
    EXPECT_NE(p->stage, PreviewStage::final) << "a final chain ran to its end";
    if (p->stage == PreviewStage::cut) cut = p;
  }
  ASSERT_TRUE(cut);
  EXPECT_EQ(cut->revision, 1);
  EXPECT_NE(cut->note.find("cut short"), std::string::npos) << cut->note;
  EXPECT_TRUE(cut->verdicts.empty());
  // The export still writes what `sample` makes from the exported model.
  session.export_preview("cut", false);
  const model::ShapeProcessModel exported = io::read_model(dir.file("cut.json"));
  const std::string written = testing::read_file(dir.file("cut.svg"));
  const std::string body = written.substr(written.find("</metadata>") + 11);
  EXPECT_EQ(svg_of(sample_output(exported, {{40, 40}, 7}, {}, nullptr).scene),
            written.substr(0, written.find("<metadata")) + body.substr(1));
}

TEST(StudioSession, RefusesA3DModelAndBadSizes) {
  const testing::TempDir dir;
  StudioInput input = squares_input(dir.path());
  input.preview_size = {40, -1};
  EXPECT_THROW(StudioSession{input}, core::ArgumentError);
  input = squares_input(dir.path());
  input.model->dimension = 3;
  EXPECT_THROW(StudioSession{input}, core::ArgumentError);
}

}  // namespace
}  // namespace shapeproc::studio
