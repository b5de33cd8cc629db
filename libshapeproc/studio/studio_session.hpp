// A studio session: one model being edited and its live preview. The session fits the exemplar
// first when given one (progress in its state), then keeps a worker thread that samples the
// preview of the newest revision: a draft continued from the picture on screen, then the output
// `shapeproc sample` makes with the same model, size and seed, judged against the exemplar. Every
// edit, undo, seed or size change makes a new revision and cancels the preview being sampled: the
// newest edit always wins. All members are safe to call from several threads (the server's).
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "libshapeproc/evaluation/verdicts.hpp"
#include "libshapeproc/fit/fit_exemplar.hpp"
#include "libshapeproc/geometry/scene.hpp"
#include "libshapeproc/model/shape_process_model.hpp"
#include "libshapeproc/studio/model_edit.hpp"

namespace shapeproc::studio {

struct StudioInput {
  // What to edit: a model, or else the exemplar's fit (`fit`). With an exemplar, previews are
  // judged against it; a model alone gets no verdicts.
  std::optional<model::ShapeProcessModel> model;
  std::optional<geometry::Scene> exemplar;
  bool tile = false;  // the exemplar is one period of a seamless repeat
  fit::ExemplarFitOptions fit;
  // Completes the fitted model's record (the exemplar's file, the fit's options); may be empty.
  std::function<void(model::ShapeProcessModel&)> record_fit;
  std::string source;                  // the file the session opened, for the edits' record
  std::vector<std::string> arguments;  // the studio's command line, for the edits' record
  // The domains of the two preview sizes (W,H in the model's units).
  std::vector<double> preview_size, full_size;
  std::uint64_t seed = 1;
  std::filesystem::path export_directory = ".";  // the only place the session writes
  // A final preview's chain still running this long after the edit is stopped, and the preview
  // says so (PreviewStage::cut); exporting that revision then samples its output in full.
  double final_seconds = 5.0;
};

enum class Phase { fitting, ready, failed };

struct FitProgress {
  std::string stage;              // "quadrature", "maximum likelihood", ...
  long long done = 0, total = 0;  // of the stage (0 total: not known)
  double seconds = 0.0;           // since the fit began
};

struct StudioState {
  Phase phase = Phase::fitting;
  FitProgress fit;
  std::string error;                              // why the fit failed
  std::optional<model::ShapeProcessModel> model;  // the current model, once fitted
  std::vector<std::string> edits;                 // that made it from the fit
  bool can_undo = false, can_redo = false;
  std::uint64_t seed = 1;
  bool full = false;  // previews at the full size
  std::vector<double> size;
  long long revision = 0;
  bool has_exemplar = false;
};

// A draft (the picture on screen continued under the edited model), the final picture (what
// `sample` makes), or a final chain cut short at StudioInput::final_seconds (the draft's picture
// stays on screen, with a note).
enum class PreviewStage { draft, final, cut };

struct Preview {
  long long sequence = 0;  // one more per picture published
  long long revision = 0;  // the edits it shows
  PreviewStage stage = PreviewStage::draft;
  std::string svg;  // the picture, without a record
  int elements = 0;
  long long steps = 0;
  bool stationary = true;
  double seconds = 0.0;  // from the edit to this picture
  std::uint64_t seed = 1;
  std::vector<double> size;
  std::vector<evaluation::Verdict> verdicts;  // a final preview's, with an exemplar
  std::string summary;                        // evaluation::summary of them
  std::string command;  // a final preview: the `sample` command that makes it from the export
  std::string note;     // what went wrong, or a warning ("the chain ended empty")
};

struct ExportResult {
  std::vector<std::filesystem::path> files;  // model (.json), output (.svg, .png), command (.sh)
  std::string command;
};

class StudioSession {
 public:
  // Throws core::ArgumentError for a 3D model or exemplar (previews are drawn in 2D), sizes that
  // are not two positive numbers, or neither a model nor an exemplar.
  explicit StudioSession(StudioInput input);
  ~StudioSession();  // stops the worker (a fit or chain in progress is cancelled)
  StudioSession(const StudioSession&) = delete;
  StudioSession& operator=(const StudioSession&) = delete;

  // Stops the worker (cancelling a fit or chain in progress) and wakes every request waiting for
  // a picture; the session then makes no more pictures. The destructor closes it too.
  void close();

  StudioState state() const;
  // The exemplar as SVG (empty without one).
  std::string exemplar_svg() const;

  // Each makes a new revision; edit throws core::ArgumentError (nothing changes) for an edit the
  // model refuses, and every one throws core::UsageError before the model is fitted.
  void edit(const ModelEdit& edit);
  bool undo();
  bool redo();
  bool reset();
  void reroll_seed();
  void set_seed(std::uint64_t seed);
  void set_full_size(bool full);

  // The first picture published after `after` (a sequence number), waiting at most `timeout`;
  // none when there is none by then.
  std::optional<Preview> wait_preview(long long after, std::chrono::milliseconds timeout) const;

  // Writes NAME.json (the edited model, its edits recorded), NAME.svg and NAME.png (the final
  // preview of the current revision, waited for) and NAME.sh (the command that makes NAME.svg
  // from NAME.json) into the export directory. Throws core::ArgumentError for a name that is not
  // 1-64 letters, digits, '-' or '_', or files that exist without `overwrite`.
  ExportResult export_preview(const std::string& name, bool overwrite);

 private:
  struct Shared;
  std::unique_ptr<Shared> shared_;
};

}  // namespace shapeproc::studio
