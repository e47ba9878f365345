// `pak flow`'s options, each declared once: flag, --config key, report parameter.
#include "flow_arguments.hpp"
#include "outline_output.hpp"
#include "shared_options.hpp"

namespace pak::cli {
namespace {

// FlowOptions's members.
OptionTable<FlowOptions> flowOptionTable() {
  using O = FlowOptions;
  OptionTable<O> own{
      {"count", field(&O::count), "about how many elements the automatic --gap aims for (in the whole output, both halves under --mirror)"},
      {"gap", length(&O::gap), "s_gap, the distance between neighbouring streamlines, about an element's width (canonical units: l_canvas, the larger side of the containers' bounds, is 1000); 0: worked out from --count, the free area and the elements' proportions"},
      {"min-length", length(&O::minLength), "s_min: shorter streamlines get no element (canonical units); 0: in proportion to the gap and the elements' median length-to-width ratio (the report's density gives the value used)"},
      {"max-length", length(&O::maxLength), "s_max: streamlines stop before this length (canonical units); 0: in proportion to the gap and that ratio"},
      {"stop-ratio", field(&O::stopRatio), "s_stop = ratio × s_gap: a streamline stops this close to another"},
      {"sample-spacing", length(&O::sampleSpacing), "sampling of guides, boundaries and streamlines (canonical units; thesis 0.005 l_canvas)"},
      {"field-resolution", field(&O::fieldResolution), "vector field grid cells along the longer side"},
      {"blob-resolution", field(&O::blobResolution), "blob (Voronoi) grid cells along the longer side"},
      {"lr-samples", field(&O::lrSamples), "n_f, samples of the LR functions"},
      {"widen", field(&O::widen), "each side of an element widens, smoothly along it, where its blob leaves room, up to this many times the element's uniform width (1: uniform width, as in the thesis)"},
      {"widen-margin", field(&O::widenMargin), "with --widen: an element widens only into room farther than this many --spacing from its blob's edge, so wide channels and pockets narrow, not every channel"},
      {"spacing", length(&O::spacing), "space kept between elements, and between elements and walls (canonical units); negative: in proportion to the gap"},
      {"iterations", field(&O::iterations), "refinement iterations (Algorithm 2)"},
      {"time-limit", field(&O::timeLimit), "stop refining after this many seconds and write the packing as it is then, with stop-reason time-limit in the report (0: no limit; a run stopped by it depends on the machine's speed). Ctrl-C does the same (interrupted); a second Ctrl-C aborts, leaving no half-written file"},
      {"growth-tolerance", field(&O::growthTolerance), "α: a refined placement is kept when its area is at least α × the old one"},
      {"growth-limit", length(&O::growthLimit), "g_limit: how far a streamline end or a blob moves per iteration (canonical units)"},
      {"max-rotation", field(&O::maxRotationDegrees), "refinement tries rotations of ±1…N degrees"},
      {"infill-every", field(&O::infillEvery), "after every N-th refinement iteration, pockets the streamlines left (where they stop, converge or part) each get a new streamline and element, which refinement then grows (0: none, as in the thesis)"},
      {"infill-width", field(&O::infillWidth), "with --infill-every: a pocket gets an element when the room in it, past the spacing, is at least this many --gap wide"},
      {"infill-min-area", field(&O::infillMinArea), "with --infill-every: an element placed in a pocket is kept when its area is at least this share of the median element's"},
      {"keep-folds", field(&O::keepFolds), "keep bent elements that fold over themselves (a turn sharper than the element is wide), as the thesis does; by default the element goes on the longer side of the spine's sharpest turn (up to four cuts), else the placement is refused"},
      {"shift-distance-weight", field(&O::shiftDistanceWeight), "w_d of eq. 3.2: keeps a shifted streamline near the old one"},
      {"shift-field-weight", field(&O::shiftFieldWeight), "w_f of eq. 3.2: keeps a shifted streamline along the field"},
      {"shift-field-power", field(&O::shiftFieldPower), "p of eq. 3.2"},
      {"shift-neighbours", field(&O::shiftNeighbours), "nearest nodes examined from each node when shifting a streamline"},
      {"fill-gaps", field(&O::fillGaps), "add shapes made from the negative space between the elements (thesis Fig. 3.15)"},
      {"fill-gaps-inset", length(&O::fillGapsInset), "with --fill-gaps: the gap shapes' inset from the elements (canonical units; 0: spacing / 2)"},
  };
  return own + mounted(runOptions(), field(&O::run));
}

// What the run reads itself (--polyline) or parses into FlowOptions (--mirror).
OptionTable<FlowArguments> textOptionTable() {
  using A = FlowArguments;
  return {
      {"mirror", field(&A::mirror), "pack one side of a line and reflect it across (thesis Fig. 3.13): x=VALUE packs the part left of that vertical line, y=VALUE the part above that horizontal one, X1,Y1,X2,Y2 the part on the left of a walk from (X1, Y1) to (X2, Y2) as seen on screen (input units)"},
      {"polyline", field(&A::polyline), polylineHelp(kFlowCurveTolerance) + " (thesis 3.4 post-processes its output into curves too)"},
  };
}

}  // namespace

const OptionTable<FlowArguments>& flowOptions() {
  using A = FlowArguments;
  static const OptionTable<A> table = mounted(flowOptionTable(), field(&A::options)) + textOptionTable();
  return table;
}

}  // namespace pak::cli
