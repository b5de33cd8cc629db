#include "tools/cli/method_flags.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/graph_svg_writer.hpp"
#include "libshapeproc/io/number_rows.hpp"
#include "libshapeproc/io/png_reader.hpp"
#include "libshapeproc/io/text.hpp"
#include "tools/cli/flags.hpp"

namespace shapeproc::cli {

namespace {

// An orientation (flow) field from --orientation-field: none, a constant angle or a PNG.
methods::OrientationField orientation_field(const std::string& orientation,
                                            const geometry::Domain& domain) {
  if (orientation.empty()) return {};
  if (io::extension_of(orientation) == "png")
    return methods::OrientationField::map(
        std::make_shared<const geometry::Raster>(io::read_grayscale_png(orientation)),
        domain.box());
  const auto angle = io::parse_number_list(orientation);
  if (!angle || angle->size() != 1)
    throw core::UsageError("--orientation-field: expected an angle in degrees or a .png, got '" +
                           orientation + "'");
  return methods::OrientationField::constant((*angle)[0]);
}

}  // namespace

void EmFlags::add_shared_to(CLI::App& command) {
  command
      .add_option("--neighbourhood", rings, "ma-em, davison: neighbourhood size in rings (1 to 3)")
      ->check(CLI::Range(0.25, 10.0))
      ->capture_default_str();
  command.add_option("--k", k, "ma-em, davison: k-coherence similarity set size")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  command
      .add_option("--alpha", alpha,
                  "ma-em, davison: weight of an attribute mismatch, in squared mean nearest "
                  "distances")
      ->check(non_negative_number())
      ->capture_default_str();
}

void EmFlags::add_to(CLI::App& command) {
  command
      .add_option("--lambda", lambda,
                  "ma-em: weight of the domain-shape term, in squared mean nearest distances")
      ->check(non_negative_number())
      ->capture_default_str();
  command
      .add_option("--samples-per-element", samples,
                  "ma-em: samples per element, 1 to 16, or auto (from each shape's elongation)")
      ->capture_default_str();
  command.add_flag("--copy-patches", copy_patches,
                   "ma-em: let patch copy continue a neighbouring cell's exemplar patch, as the "
                   "paper (a seamless tile then comes out repeated)");
  command.add_option("--initialisation", initialisation, "ma-em: the starting output")
      ->check(CLI::IsMember({"patch-copy", "random-copy", "incremental-add"}))
      ->capture_default_str();
  command.add_option("--search", search, "ma-em: k-coherence or brute-force search")
      ->check(CLI::IsMember({"k-coherence", "brute-force"}))
      ->capture_default_str();
  command
      .add_option("--reconstruction", reconstruction,
                  "ma-em: how elements are rebuilt from their samples")
      ->check(CLI::IsMember({"rigid", "similarity", "tps", "tps-approx"}))
      ->capture_default_str();
  CLI::Option* flag =
      command.add_flag("--physics", physics,
                       "ma-em: interleave rigid-body steps (Box2D in 2D, Bullet in 3D) that push "
                       "interpenetrating elements apart");
  command
      .add_option("--physics-steps", physics_steps,
                  "ma-em: engine steps per EM iteration with --physics")
      ->check(CLI::Range(1, 1000))
      ->needs(flag)
      ->capture_default_str();
}

void EmFlags::add_orientation_to(CLI::App& command) {
  command.add_option("--orientation-field", orientation,
                     "ma-em, ijiri (2D): a constant angle in degrees, or a grayscale PNG "
                     "stretched over --size (grey g turns the exemplar's frame by 360 g "
                     "degrees); ijiri takes it with --rotation flow-field");
}

methods::EmOptions EmFlags::options(const geometry::Domain& domain, long long iterations) const {
  methods::EmOptions o;
  o.rings = rings;
  o.k = k;
  o.alpha = alpha;
  o.lambda = lambda;
  if (samples != "auto") {
    const auto n = io::parse_number_list(samples);
    if (!n || n->size() != 1 || (*n)[0] != std::floor((*n)[0]) || (*n)[0] < 1 ||
        (*n)[0] > methods::kMaxSamplesPerElement)
      throw core::UsageError("--samples-per-element: expected 1 to 16 or auto, got '" + samples +
                             "'");
    o.samples.per_element = static_cast<int>((*n)[0]);
  }
  o.initialisation = methods::parse_initialisation(initialisation);
  o.diverse_patches = !copy_patches;
  o.search =
      search == "brute-force" ? methods::SearchRule::brute_force : methods::SearchRule::k_coherence;
  o.reconstruction = methods::parse_reconstruction(reconstruction);
  o.physics_steps = physics ? physics_steps : 0;
  if (iterations > 10000) throw core::UsageError("--iterations: ma-em takes at most 10000");
  if (iterations > 0) o.iterations = static_cast<int>(iterations);
  o.orientation = orientation_field(orientation, domain);
  return o;
}

void GrowthFlags::add_overlap_to(CLI::App& command) {
  command
      .add_option("--overlap", overlap,
                  "davison, ijiri: overlap test of new elements: the shapes themselves (ijiri: "
                  "turns then snap to 0.5 degrees), bounding circles (spheres, of half each "
                  "exemplar element's nearest distance, as davison's paper) or none (ijiri's "
                  "default, as the paper); davison's default: shapes, circles for a lattice")
      ->check(CLI::IsMember({"circles", "shapes", "none"}));
}

void GrowthFlags::add_to(CLI::App& command) {
  command
      .add_option("--ratio", ratio,
                  "davison: a candidate that can grow is taken only within this ratio of the "
                  "best candidate's neighbourhood distance (> 1)")
      ->check(CLI::Range(1.0 + 1e-9, 1e6))
      ->capture_default_str();
  command
      .add_option("--patch-radius", patch_radius,
                  "davison: a copied exemplar patch grows at most this many neighbourhood radii "
                  "from where it began, then a new one begins (diversity; 0: off, as the paper)")
      ->check(non_negative_number())
      ->capture_default_str();
  command
      .add_option("--bounding-radius", bounding_radius,
                  "davison: every element's bounding radius (default: half each exemplar "
                  "element's nearest distance, within its bounding circle)")
      ->check(non_negative_number());
  command.add_flag("--no-calibrate", no_calibrate,
                   "davison: grow as the paper does, however much denser than the exemplar "
                   "(default: a copy's neighbourhood may hold at most c times the exemplar's "
                   "mean count, c chosen by pilot growths; see docs/methods.md)");
  command.add_flag("--no-optimise", no_optimise,
                   "davison: grow without the least-squares relaxation of the front");
  command.add_option("--palette", palette,
                     "davison: a second exemplar (read as the first) grown beside it, each with "
                     "its own neighbourhood and bounding radii, from the two halves of the "
                     "domain's longest axis until they meet (Davison's example palette)");
  command
      .add_option("--palette-neighbourhood", palette_rings,
                  "davison: the second exemplar's neighbourhood in rings of its own spacing "
                  "(default: --neighbourhood)")
      ->check(CLI::Range(1e-9, 10.0));
  command
      .add_option("--palette-bounding-radius", palette_bounding_radius,
                  "davison: the second exemplar's bounding radius (default: automatic)")
      ->check(non_negative_number());
}

methods::GrowthOptions GrowthFlags::options(const EmFlags& shared) const {
  methods::GrowthOptions o;
  o.rings = shared.rings;
  o.k = shared.k;
  o.alpha = shared.alpha;
  o.ratio = ratio;
  o.patch_radius = patch_radius;
  o.bounding_radius = bounding_radius;
  o.optimise = !no_optimise;
  o.calibrate_density = !no_calibrate;
  if (overlap == "none")
    throw core::UsageError("--overlap none: --method davison tests circles or shapes");
  if (!overlap.empty()) o.exact_overlap = overlap == "shapes";
  return o;
}

void IjiriFlags::add_to(CLI::App& command) {
  command
      .add_option("--rotation", rotation,
                  "ijiri: none (references keep their orientation), best (each match turned to "
                  "fit) or flow-field (turned by --orientation-field)")
      ->check(CLI::IsMember({"none", "best", "flow-field"}))
      ->capture_default_str();
  command.add_option("--edge-flips", flips,
                     "ijiri: file of exemplar edges to flip, one 'i j' pair of element indices "
                     "per line ('#' comments)");
  command.add_option("--seeds", seeds,
                     "ijiri: file of initial seed positions, one 'x y' per line (default: one "
                     "seed at the centre)");
  command.add_option("--priority", priority,
                     "ijiri: seed priorities by exemplar category, NAME=P,... (higher grows "
                     "first within 5 mean edge lengths)");
  command.add_option("--weights", weights, "ijiri: w1,w2,w3 of eq. 2 (distance, symbol, sub-id)")
      ->capture_default_str();
  command.add_flag("--no-relax", no_relax, "ijiri: grow without the relaxation of eq. 5");
  command.add_option("--show-connectivity", show,
                     "ijiri: also draw the exemplar's connectivity (after --edge-flips) to this "
                     ".svg, elements labelled by index, border elements hollow");
}

methods::SeedGrowthOptions IjiriFlags::options(const geometry::Scene& exemplar,
                                               const std::string& orientation,
                                               const std::string& overlap,
                                               const geometry::Domain& domain) const {
  methods::SeedGrowthOptions o;
  o.exact_overlap = overlap == "shapes";
  o.circle_overlap = overlap == "circles";
  o.rotation = methods::parse_rotation_mode(rotation);
  o.field = orientation_field(orientation, domain);
  if (o.rotation == methods::RotationMode::flow_field && o.field.empty())
    throw core::UsageError("--rotation flow-field needs --orientation-field");
  if (o.rotation != methods::RotationMode::flow_field && !o.field.empty())
    throw core::UsageError(
        "--orientation-field: --method ijiri takes it with --rotation "
        "flow-field");
  const auto w = io::parse_number_list(weights);
  if (!w || w->size() != 3 || (*w)[0] < 0 || (*w)[1] < 0 || (*w)[2] < 0)
    throw core::UsageError("--weights: expected three numbers >= 0 (w1,w2,w3), got '" + weights +
                           "'");
  o.w1 = (*w)[0];
  o.w2 = (*w)[1];
  o.w3 = (*w)[2];
  o.relax = !no_relax;
  if (!flips.empty())
    for (const auto& row : io::read_number_rows(flips, 2)) {
      if (row[0] != std::floor(row[0]) || row[1] != std::floor(row[1]) || row[0] < 0 ||
          row[1] < 0 || row[0] >= 1e9 || row[1] >= 1e9)
        throw core::UsageError(flips + ": element indices must be whole numbers >= 0");
      o.flips.push_back({static_cast<int>(row[0]), static_cast<int>(row[1])});
    }
  if (!seeds.empty())
    for (const auto& row : io::read_number_rows(seeds, 2))
      o.seeds.emplace_back(row[0], row[1], 0.0);
  if (!priority.empty()) {
    o.priority.assign(exemplar.categories.size(), 0);
    for (const std::string& item : io::split(priority, ',')) {
      const auto equals = item.find('=');
      const auto value =
          equals == std::string::npos ? std::nullopt : io::parse_number(item.substr(equals + 1));
      if (!value || *value != std::floor(*value))
        throw core::UsageError("--priority: expected NAME=P with a whole P, got '" + item + "'");
      const std::string name(io::trim(item.substr(0, equals)));
      bool found = false;
      for (std::size_t c = 0; c < exemplar.categories.size(); ++c)
        if (exemplar.categories[c].name == name) {
          o.priority[c] = static_cast<int>(*value);
          found = true;
        }
      if (!found) throw core::UsageError("--priority: the exemplar has no category '" + name + "'");
    }
  }
  return o;
}

// The exemplar's connectivity as a picture (--show-connectivity).
void show_connectivity(const methods::SeedGrowthExemplar& exemplar, const std::string& file) {
  std::vector<geometry::Vec3> nodes;
  std::vector<bool> open;
  for (std::size_t e = 0; e < exemplar.scene.elements.size(); ++e) {
    nodes.push_back(exemplar.domain.wrap(exemplar.scene.elements[e].position));
    open.push_back(!exemplar.connectivity.rings[e].closed);
  }
  std::vector<io::GraphEdge> edges;
  for (const auto& [first, offset] : methods::ring_edges(exemplar.connectivity))
    edges.push_back({first, offset});
  io::write_graph_svg(file, exemplar.scene.window, nodes, edges, open);
}

}  // namespace shapeproc::cli
