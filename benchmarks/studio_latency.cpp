// The studio's edit-to-picture time (run ./build/benchmarks/studio_latency MODEL EXEMPLAR
// [--tile] [--category-by fill|class|layer]; scripts/studio-latency.sh runs it on data/svg):
// a session on the fitted model, judged against its exemplar, previews at twice the exemplar's
// width and height (four times its area). After its first picture, 12 edits one after another
// (γ of the first band of pair 0, every axis, up and down by ×2; β ×1.25 and back), each waited
// for to its final preview. Prints per edit the seconds to the first picture (a draft continued
// from the one on screen) and to the final one (the chain `sample` runs, and the verdicts), and
// a summary line: "median draft S max draft S median final S max final S elements N draft/final
// R cut C" (C: the final chains cut short at the studio's time limit, of 12; R: the median ratio of
// the draft's element count to the final picture's, how near the draft comes to the edited model's
// equilibrium).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/io/model_io.hpp"
#include "libshapeproc/io/scene_io.hpp"
#include "libshapeproc/studio/studio_session.hpp"

namespace {

using namespace shapeproc;
using namespace std::chrono_literals;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

struct Timing {
  double draft = -1, final = 0;  // seconds from the edit
  int draft_elements = 0, elements = 0;
  bool cut = false;  // the final chain was cut short at the studio's time limit
};

// The draft's and the final picture's seconds after an edit of revision `revision`.
Timing wait_for(const studio::StudioSession& session, long long revision, long long& after) {
  Timing t;
  for (;;) {
    const auto p = session.wait_preview(after, 120'000ms);
    if (!p) throw std::runtime_error("no preview within two minutes");
    after = p->sequence;
    if (p->revision != revision) continue;
    if (t.draft < 0) {
      t.draft = p->seconds;
      t.draft_elements = p->elements;
    }
    if (p->stage != studio::PreviewStage::draft) {
      t.final = p->seconds;
      t.elements = p->elements;
      t.cut = p->stage == studio::PreviewStage::cut;
      return t;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: studio_latency MODEL.json EXEMPLAR [--tile] [--category-by KIND]\n");
    return 2;
  }
  try {
    io::ReaderOptions reader;
    bool tile = false;
    for (int k = 3; k < argc; ++k) {
      if (std::strcmp(argv[k], "--tile") == 0) tile = reader.tile = true;
      if (std::strcmp(argv[k], "--category-by") == 0 && k + 1 < argc)
        reader.category_by = io::CategoryRule::parse(argv[++k]);
    }
    studio::StudioInput input;
    input.model = io::read_model(argv[1]);
    input.exemplar = io::read_scene(argv[2], reader);
    input.tile = tile;
    const geometry::Vec3 sides = input.exemplar->window.sizes();
    input.preview_size = {2 * sides.x(), 2 * sides.y()};
    input.full_size = {4 * sides.x(), 4 * sides.y()};
    input.export_directory = "/nonexistent";  // never written
    studio::StudioSession session(std::move(input));
    long long after = 0;
    const Timing first = wait_for(session, 1, after);
    std::printf("first picture %.3f s, %d elements\n", first.final, first.elements);
    const double beta = session.state().model->categories[0].beta;
    std::vector<double> drafts, finals, ratios;
    int elements = 0, cut = 0;
    for (int e = 0; e < 12; ++e) {
      studio::ModelEdit edit;
      if (e % 4 < 2) {
        const double gamma = session.state().model->interactions.at(0).axes[0].gammas.at(0);
        edit = {studio::EditKind::gamma, 0, 0, 0, true, e % 4 == 0 ? gamma * 2 + 0.05 : gamma / 2};
      } else {
        edit = {studio::EditKind::beta, 0, 0, 0, false, e % 4 == 2 ? beta * 1.25 : beta};
      }
      session.edit(edit);
      const Timing t = wait_for(session, session.state().revision, after);
      std::printf("edit %2d: draft %.3f s (%d elements), final %.3f s (%d elements)%s\n", e + 1,
                  t.draft, t.draft_elements, t.final, t.elements, t.cut ? ", cut short" : "");
      cut += t.cut;
      drafts.push_back(t.draft);
      finals.push_back(t.final);
      ratios.push_back(t.elements > 0 ? static_cast<double>(t.draft_elements) / t.elements : 0.0);
      elements = t.elements;
    }
    std::printf(
        "median draft %.3f max draft %.3f median final %.3f max final %.3f elements %d "
        "draft/final %.2f cut %d\n",
        median(drafts), *std::max_element(drafts.begin(), drafts.end()), median(finals),
        *std::max_element(finals.begin(), finals.end()), elements, median(ratios), cut);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "studio_latency: %s\n", e.what());
    return 2;
  }
  return 0;
}
