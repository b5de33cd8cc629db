#include "libshapeproc/pipeline/method_comparison.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/core/stopwatch.hpp"
#include "libshapeproc/io/domain_io.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/io/synthesis_record_io.hpp"
#include "libshapeproc/io/text.hpp"
#include "libshapeproc/pipeline/synthesis_run.hpp"
#include "libshapeproc/synthesis/output_check.hpp"

namespace shapeproc::pipeline {

namespace {

// The request that runs `method` (a name of comparable_methods) with its defaults.
SynthesisRequest method_request(const std::string& method, const io::ReaderOptions& reader) {
  SynthesisRequest request;
  request.fit = fit::exemplar_fit_options(reader.tile);
  if (method == "centroid") request.fit.fit.measurement.distance = geometry::DistanceKind::centroid;
  if (method == "hausdorff")
    request.fit.fit.measurement.distance = geometry::DistanceKind::hausdorff;
  if (method == "centroid" || method == "hausdorff" || method == "shape-process") {
    request.method = methods::Method::shape_process;
  } else if (method.rfind("hybrid-", 0) == 0) {
    request.method = methods::Method::hybrid;
    request.options.start_from = *methods::method_from_name(method.substr(7));
  } else {
    request.method = *methods::method_from_name(method);
  }
  return request;
}

// The message of an error a method failed with, its options left as {name} marks.
std::string failure_of(const std::exception_ptr& error) {
  const core::OptionNamer marks = [](std::string_view name) {
    return "{" + std::string(name) + "}";
  };
  try {
    std::rethrow_exception(error);
  } catch (const core::InputError& e) {
    return e.shown(marks);
  } catch (const core::UsageError& e) {
    return e.shown(marks);
  } catch (const core::ArgumentError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("internal error: ") + e.what();
  }
}

// Runs one method and writes its output (and the shape process's model) into the directory.
void run_method(const MethodComparisonRequest& request, const geometry::Scene& exemplar,
                const geometry::Domain& domain, MethodRun& run) {
  const std::filesystem::path directory(request.directory);
  const std::string read = io::extension_of(request.exemplar);
  const std::string extension = read == "svg" || read == "csv" ? read : "obj";
  SynthesisRequest one = method_request(run.method, request.reader);
  one.source = request.exemplar;
  one.sample.chains.seed = request.seed;
  one.sample.chains.cancel = request.cancel;
  synthesis::SynthesisRecord& record = one.sample.chains.record;
  record.command = "compare";
  record.arguments = {request.command};
  record.inputs = {{"exemplar", request.exemplar}};
  record.options = {{"compared method", run.method}};
  one.fitted = [&](fit::ExemplarFit& fit) {
    if (!fit.result.model.fit) return;
    fit.result.model.fit->exemplar = request.exemplar;
    fit.result.model.fit->arguments = {request.command};
    fit.result.model.fit->options = {{"compared method", run.method}};
  };
  one.sample.ready = [&run](const synthesis::Synthesizer&, const SynthesisRun& so_far) {
    for (const std::string& line : so_far.described) run.lines.push_back(line);
    for (const std::string& line : so_far.warnings) run.lines.push_back("warning: " + line);
  };
  const SynthesisRun made = synthesize(
      exemplar, request.reader.tile ? geometry::Boundary::torus : geometry::Boundary::open, domain,
      one);
  const synthesis::SynthesisResult& result = made.results.front();
  if (run.method == "shape-process" && made.model) {
    io::write_model(*made.model, (directory / "model.json").string());
    run.lines.push_back("wrote the fitted model to " + (directory / "model.json").string());
  }
  run.output = (directory / (run.method + "." + extension)).string();
  io::write_scene(result.scene, run.output, io::synthesis_provenance(result.record));
  run.elements = result.scene.elements.size();
  run.lines.push_back(result.record.summary() + ": " + std::to_string(run.elements) + " elements");
  const synthesis::OutputCheck check =
      synthesis::check_output(result, made.exemplar_density, made.automatic_stop);
  if (check.short_of_density)
    run.lines.push_back("warning: " + std::to_string(run.elements) + " elements where the " +
                        "exemplar's density gives " + core::format_general(check.wanted, 4) +
                        " (x" + core::format_fixed(check.ratio(), 2) +
                        "): the model does not reach its exemplar's packing from empty");
}

}  // namespace

const std::vector<std::string>& comparable_methods() {
  static const std::vector<std::string> names = {
      "tile",     "shape-process", "ma-em",        "ijiri",          "davison",
      "centroid", "hausdorff",     "hybrid-ma-em", "hybrid-davison", "hybrid-ijiri"};
  return names;
}

const std::vector<std::string>& default_compared_methods() {
  static const std::vector<std::string> names = {"tile", "shape-process", "ma-em", "ijiri",
                                                 "davison"};
  return names;
}

std::vector<std::string> parse_compared_methods(const std::string& list) {
  std::vector<std::string> out;
  if (list.empty()) throw core::UsageError("{methods}: no method given");
  const std::vector<std::string>& known = comparable_methods();
  for (const std::string& name : io::split(list, ',')) {
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw core::UsageError("{methods}: unknown method '" + name +
                             "' (expected tile, shape-process, ma-em, ijiri, davison, centroid, "
                             "hausdorff, hybrid-ma-em, hybrid-davison or hybrid-ijiri)");
    if (std::find(out.begin(), out.end(), name) != out.end())
      throw core::UsageError("{methods}: '" + name + "' is given twice");
    out.push_back(name);
  }
  return out;
}

MethodComparison compare_methods(const MethodComparisonRequest& request) {
  // The exemplar read once before anything runs: a bad file is one error, not one per method.
  const geometry::Scene exemplar = io::read_scene(request.exemplar, request.reader);
  const auto size = io::parse_size(request.size, &exemplar.window);
  if (!size || static_cast<int>(size->size()) != exemplar.dimension)
    throw core::UsageError(
        "{size}: expected " + std::string(exemplar.dimension == 3 ? "W,H,D" : "W,H") +
        " (positive) for a " + std::to_string(exemplar.dimension) +
        "D exemplar, or multiples of its window such as 3W,3H; got '" + request.size + "'");
  const std::filesystem::path directory(request.directory);
  if (std::filesystem::exists(directory) && !std::filesystem::is_directory(directory))
    throw core::UsageError(request.directory + ": exists and is not a directory");
  const geometry::Domain domain = io::read_domain({*size, "", "", ""}, exemplar.dimension);
  std::filesystem::create_directories(directory);
  report::ComparisonRequest page;
  page.exemplar = request.exemplar;
  page.directory = request.directory;
  page.reader = request.reader;
  page.metrics = request.metrics;
  page.command = request.command;
  MethodComparison out;
  std::string first_failure;
  for (std::size_t i = 0; i < request.methods.size(); ++i) {
    MethodRun run;
    run.method = request.methods[i];
    if (request.starting) request.starting(i + 1, request.methods.size(), run.method);
    const core::Stopwatch watch;
    try {
      run_method(request, exemplar, domain, run);
    } catch (const core::Cancelled&) {
      throw;
    } catch (...) {
      run.failure = failure_of(std::current_exception());
      run.output.clear();
      if (first_failure.empty()) first_failure = run.method + ": " + run.failure;
    }
    run.seconds = watch.seconds();
    if (run.failure.empty()) {
      page.outputs.push_back(run.output);
      page.labels.push_back(run.method);
      page.timings.emplace_back(run.method, run.seconds);
      if (run.method == "shape-process") page.model = (directory / "model.json").string();
    }
    if (request.finished) request.finished(run);
    out.runs.push_back(std::move(run));
  }
  if (page.outputs.empty())
    throw core::UsageError("no method could synthesise from " + request.exemplar + ": " +
                           first_failure);
  out.report = report::write_comparison_report(page);
  return out;
}

}  // namespace shapeproc::pipeline
