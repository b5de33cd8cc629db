// The tile-fitting policy: a small tile is fitted repeated, and refitted once on a repeat that
// holds the interactions its first fit found; a fit that would need too many repeats says so;
// the refinement (the maximum likelihood) runs once, on the repeat chosen.
#include "libshapeproc/fit/tile_fit.hpp"

#include <gtest/gtest.h>

#include "libshapeproc/geometry/arc.hpp"

namespace shapeproc::fit {
namespace {

using geometry::Box3;
using geometry::Vec3;

// Two dots of radius 1 on a 10 x 6 tile (extent √2 each).
geometry::Scene two_dot_tile() {
  geometry::Scene tile;
  tile.window = Box3(Vec3(0, 0, 0), Vec3(10, 6, 0));
  tile.categories.push_back({"dots"});
  for (const geometry::Vec2& centre : {geometry::Vec2(2, 3), geometry::Vec2(7, 3)}) {
    geometry::Drawable2 dot;
    dot.paths.push_back(geometry::ellipse_path(centre, 1, 1));
    geometry::add_element(tile, geometry::Shape{geometry::PlanarShape{{dot}}, "dot"}, 0);
  }
  return tile;
}

// A fit stand-in whose model reaches `range`, recording the repeats it was called with.
struct StubFit {
  double range;
  std::vector<int> calls;
  FitResult operator()(const geometry::Scene& scene, int repeats) {
    calls.push_back(repeats);
    EXPECT_EQ(scene.elements.size(), 2u * static_cast<std::size_t>(repeats * repeats));
    FitResult r;
    model::PairInteraction pair;
    model::AxisParameters axis;
    axis.thresholds = {0.0, range};
    axis.gammas = {1.0};
    pair.axes = {axis};
    r.model.interactions = {pair};
    return r;
  }
};

TEST(TileFit, RefitsOnceOnARepeatThatHoldsTheRange) {
  const geometry::Scene tile = two_dot_tile();
  // Range 3: 2 (3 + 2√2) = 11.7 < 18, the 3 x 3 repeat's smaller side: one fit.
  StubFit near{3.0, {}};
  TileFit fit = fit_tile(tile, std::ref(near));
  EXPECT_EQ(near.calls, std::vector<int>({3}));
  EXPECT_EQ(fit.repeats, 3);
  EXPECT_TRUE(fit.notes.empty());
  // Range 10: 2 (10 + 2√2) = 25.7, five repeats of 6: fitted again on 5 x 5, with a note.
  StubFit far{10.0, {}};
  fit = fit_tile(tile, std::ref(far));
  EXPECT_EQ(far.calls, std::vector<int>({3, 5}));
  EXPECT_EQ(fit.repeats, 5);
  EXPECT_EQ(fit.exemplar.elements.size(), 50u);
  ASSERT_EQ(fit.notes.size(), 1u);
  EXPECT_NE(fit.notes[0].find("fitted on the tile repeated 5 x 5"), std::string::npos);
  // Range 40 would need 15 repeats: not refitted, said so.
  StubFit beyond{40.0, {}};
  fit = fit_tile(tile, std::ref(beyond));
  EXPECT_EQ(beyond.calls, std::vector<int>({3}));
  ASSERT_EQ(fit.notes.size(), 1u);
  EXPECT_NE(fit.notes[0].find("15 x 15"), std::string::npos) << fit.notes[0];
}

TEST(TileFit, TheRefinementRunsOnceOnTheRepeatChosen) {
  const geometry::Scene tile = two_dot_tile();
  StubFit far{10.0, {}};
  std::vector<int> refined;
  const TileFit fit =
      fit_tile(tile, std::ref(far), [&](const geometry::Scene& scene, int repeats, FitResult r) {
        refined.push_back(repeats);
        EXPECT_EQ(scene.elements.size(), 2u * static_cast<std::size_t>(repeats * repeats));
        r.notes.push_back("refined");
        return r;
      });
  EXPECT_EQ(far.calls, std::vector<int>({3, 5}));
  EXPECT_EQ(refined, std::vector<int>({5}));
  EXPECT_EQ(fit.result.notes, std::vector<std::string>({"refined"}));
}

TEST(TileFit, ATileOfEightElementsIsFittedOnItsOwnTorus) {
  geometry::Scene tile = two_dot_tile();
  for (int k = 0; k < 3; ++k) {
    geometry::Scene more = two_dot_tile();
    for (geometry::Element e : more.elements) tile.elements.push_back(e);
  }
  StubFit far{10.0, {}};
  const TileFit fit = fit_tile(tile, [&](const geometry::Scene& scene, int /*repeats*/) {
    EXPECT_EQ(scene.elements.size(), 8u);
    return far(two_dot_tile(), 1);
  });
  EXPECT_EQ(fit.repeats, 1);
  EXPECT_TRUE(fit.notes.empty());
}

}  // namespace
}  // namespace shapeproc::fit
