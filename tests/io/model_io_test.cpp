#include "libshapeproc/io/model_io.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/fit/fit_shape_process.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/model/interaction.hpp"
#include "libshapeproc/render/interaction_plot.hpp"
#include "tests/test_support.hpp"

namespace shapeproc::io {
namespace {

const char* kMinimal = R"({
  "format": "shapeproc-model", "version": 1, "dimension": 2,
  "categories": [ { "name": "dots", "beta": 0.01 } ],
  "interaction": [ { "categories": [0, 0], "axes": [
      { "direction": [1, 0], "thresholds": [2, 5, 9], "gammas": [0.2, 1.5] },
      { "direction": [0, 1], "thresholds": [1, 3], "gammas": [0.5] } ] } ],
  "shapes": [ { "category": 0, "geometry": { "type": "paths", "parts": [ { "d": "M0 0h4v2h-4z" } ] } } ]
})";

TEST(ModelFile, MinimalHandWrittenModelLoads) {
  const model::ShapeProcessModel m = parse_model(kMinimal, "m.json");
  EXPECT_EQ(m.measurement.directions, 4);                                 // inferred from two axes
  EXPECT_EQ(m.categories[0].beta_status, model::ParameterStatus::fixed);  // set by hand
  EXPECT_EQ(m.shapes.size(), 1u);
  EXPECT_NEAR(geometry::bounding_box(m.shapes[0].shape).center().norm(), 0.0,
              1e-12);  // centred on load
  const model::Interaction interaction(m);
  EXPECT_DOUBLE_EQ(interaction.range(), 9.0);
  EXPECT_EQ(interaction.band(0, 0, 0, 1.9), model::Interaction::kHardCore);
  EXPECT_EQ(interaction.band(0, 0, 0, 2.0), 0);  // half-open bands: [2, 5)
  EXPECT_EQ(interaction.band(0, 0, 0, 5.0), 1);
  EXPECT_EQ(interaction.band(0, 0, 0, 9.0), model::Interaction::kBeyond);
  EXPECT_EQ(interaction.band(0, 0, 1, 2.0), 0);
  EXPECT_DOUBLE_EQ(interaction.log_gamma(0, 0, 0, 1), std::log(1.5));
}

TEST(ModelFile, FitWriteReadRoundTrip) {
  const geometry::Scene exemplar = read_scene(testing::data_path("svg/crescents-grid.svg"), {});
  fit::FitOptions options;
  options.quadrature = 12;
  const fit::FitResult fit = fit::fit_shape_process(exemplar, options);
  const testing::TempDir dir;
  write_model(fit.model, dir.file("m.json"));
  const model::ShapeProcessModel back = read_model(dir.file("m.json"));
  ASSERT_EQ(back.categories.size(), fit.model.categories.size());
  EXPECT_EQ(back.categories[0].beta, fit.model.categories[0].beta);
  // crescents-grid has no finite MPLE: its β follows the data points' share.
  EXPECT_EQ(fit.model.categories[0].beta_status, model::ParameterStatus::unbounded);
  EXPECT_EQ(back.categories[0].beta_status, model::ParameterStatus::unbounded);
  EXPECT_EQ(back.interactions[0].axes[2].thresholds, fit.model.interactions[0].axes[2].thresholds);
  EXPECT_EQ(back.interactions[0].axes[2].gammas, fit.model.interactions[0].axes[2].gammas);
  EXPECT_EQ(back.interactions[0].axes[2].status, fit.model.interactions[0].axes[2].status);
  ASSERT_EQ(back.shapes.size(), exemplar.shapes.size());
  EXPECT_EQ(geometry::primitive_count(back.shapes[3].shape),
            geometry::primitive_count(exemplar.shapes[3]));
  EXPECT_EQ(model_to_json(back), model_to_json(read_model(dir.file("m.json"))));
  // Its crescents are of many sizes: size classes, kept by the file.
  ASSERT_GE(fit.model.shape_classes.size(), 2u);
  ASSERT_EQ(back.shape_classes.size(), fit.model.shape_classes.size());
  for (std::size_t k = 0; k < back.shape_classes.size(); ++k) {
    EXPECT_EQ(back.shape_classes[k].weight, fit.model.shape_classes[k].weight);
    EXPECT_EQ(back.shape_classes[k].label, fit.model.shape_classes[k].label);
  }
  for (std::size_t s = 0; s < back.shapes.size(); ++s)
    EXPECT_EQ(back.shapes[s].shape_class, fit.model.shapes[s].shape_class);
  // Where its elements have their neighbours, for births near them.
  ASSERT_FALSE(fit.model.neighbour_offsets.empty());
  ASSERT_EQ(back.neighbour_offsets.offsets.size(), fit.model.neighbour_offsets.offsets.size());
  EXPECT_EQ(back.neighbour_offsets.radii, fit.model.neighbour_offsets.radii);
  EXPECT_EQ(back.neighbour_offsets.offsets[0].offset,
            fit.model.neighbour_offsets.offsets[0].offset);
  // The plot is an SVG with one polar sector per axis half and band.
  const std::string svg = render::interaction_plot_svg(back);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("hard core"), std::string::npos);
}

struct BadModel {
  const char* name;
  std::string from, to;  // replace in kMinimal
  const char* message;
};

class ModelFileBad : public ::testing::TestWithParam<BadModel> {};

TEST_P(ModelFileBad, ClearErrors) {
  const BadModel& bad = GetParam();
  std::string text = kMinimal;
  const std::size_t at = text.find(bad.from);
  ASSERT_NE(at, std::string::npos) << bad.from;
  text.replace(at, bad.from.size(), bad.to);
  try {
    parse_model(text, "m.json");
    FAIL() << bad.name;
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(bad.message), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("m.json", 0), 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ModelFileBad,
    ::testing::Values(
        BadModel{"format", "shapeproc-model", "other", "format"},
        BadModel{"version", "\"version\": 1", "\"version\": 7", "version"},
        BadModel{"beta", "\"beta\": 0.01", "\"beta\": 0", "categories[0].beta"},
        BadModel{"beta_status", "\"beta\": 0.01", "\"beta\": 0.01, \"beta_status\": \"maybe\"",
                 "categories[0].beta_status"},
        BadModel{"decreasing", "[2, 5, 9]", "[2, 9, 5]", "must not decrease"},
        BadModel{"negative_gamma", "[0.2, 1.5]", "[0.2, -1]", "gammas[1]"},
        BadModel{"gamma_count", "[0.2, 1.5]", "[0.2]", "one per band"},
        BadModel{"direction", "\"direction\": [0, 1]", "\"direction\": [1, 1]",
                 "canonical direction"},
        BadModel{"direction_dimension", "\"direction\": [0, 1]", "\"direction\": [0, 1, 0]",
                 "2D model"},
        BadModel{"category_range", "\"categories\": [0, 0]", "\"categories\": [0, 3]",
                 "category indices"},
        BadModel{"shape_category", "\"category\": 0, \"geometry\"", "\"category\": 2, \"geometry\"",
                 "shapes[0].category"},
        BadModel{"path", "M0 0h4v2h-4z", "M0 0 X", "cannot parse"},
        BadModel{"malformed", "\"dimension\": 2,", "\"dimension\": 2", "malformed JSON"},
        // A number beyond a double's range: nlohmann's out_of_range had escaped as a crash.
        BadModel{"number_overflow", "\"beta\": 0.01", "\"beta\": 1e999999",
                 "malformed JSON: number overflow parsing '1e999999'"},
        BadModel{"missing", "\"categories\": [ { \"name\"", "\"cats\": [ { \"name\"",
                 "categories: missing"},
        BadModel{"offsets_shape", "\"shapes\": [",
                 "\"neighbour_offsets\": {\"radii\": [0.1], \"offsets\": [[0, 3, 1, 0, 1]]}, "
                 "\"shapes\": [",
                 "neighbour_offsets.offsets[0]: names a shape out of range"},
        BadModel{"offsets_row", "\"shapes\": [",
                 "\"neighbour_offsets\": {\"radii\": [0.1], \"offsets\": [[0, 0, 1, 1]]}, "
                 "\"shapes\": [",
                 "neighbour_offsets.offsets[0]: expected [from, to, x, y, weight]"},
        BadModel{"offsets_radius", "\"shapes\": [",
                 "\"neighbour_offsets\": {\"radii\": [-1], \"offsets\": [[0, 0, 1, 0, 1]]}, "
                 "\"shapes\": [",
                 "neighbour_offsets.radii[0]: must be finite and > 0"}),
    [](const ::testing::TestParamInfo<BadModel>& param_info) {
      return std::string(param_info.param.name);
    });

}  // namespace
}  // namespace shapeproc::io
