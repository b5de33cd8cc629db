// Reads an exemplar, fits it and samples an output twice its size, through the installed headers
// and library: prints the exemplar's and the output's element counts.
#include <iostream>

#include "libshapeproc/fit/fit_exemplar.hpp"
#include "libshapeproc/fit/output_sampling.hpp"
#include "libshapeproc/io/scene_io.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: consumer EXEMPLAR.svg\n";
    return 2;
  }
  using namespace shapeproc;
  const geometry::Scene exemplar = io::read_scene(argv[1], {});
  fit::ExemplarFitOptions options;
  options.likelihood.reset();  // the pseudo-likelihood alone: a quick check
  const model::ShapeProcessModel model = fit::fit_exemplar(exemplar, options).result.model;
  const geometry::Vec3 sides = 2.0 * exemplar.window.sizes();
  const geometry::Domain domain =
      geometry::Domain::from_sizes({sides.x(), sides.y()}, geometry::Boundary::torus);
  core::Random random(1);
  const sample::SampleResult output = fit::output_sampler(model, domain).sample(random);
  std::cout << exemplar.elements.size() << " " << output.scene.elements.size() << "\n";
  return output.scene.elements.empty() ? 1 : 0;
}
