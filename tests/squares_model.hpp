// A model of 6 × 1 rectangles ("squares") with four axes, a hard core per axis and one band of
// γ 0.5: the sampler tests' model of shapes that interact by direction.
#pragma once

namespace shapeproc::testing {

inline const char* kSquaresModel = R"({
  "format": "shapeproc-model", "version": 1, "dimension": 2,
  "categories": [ { "name": "squares", "beta": 0.2 } ],
  "interaction": [ { "categories": [0, 0], "axes": [
      { "direction": [1, 0], "thresholds": [2, 6], "gammas": [0.5] },
      { "direction": [0.7071067811865476, 0.7071067811865476], "thresholds": [4, 6], "gammas": [0.5] },
      { "direction": [0, 1], "thresholds": [8, 10], "gammas": [0.5] },
      { "direction": [-0.7071067811865476, 0.7071067811865476], "thresholds": [4, 6], "gammas": [0.5] } ] } ],
  "shapes": [ { "category": 0, "geometry": { "type": "paths", "parts": [ { "d": "M0 0h6v1h-6z" } ] } } ]
})";

}  // namespace shapeproc::testing
