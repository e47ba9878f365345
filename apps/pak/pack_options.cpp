// `pak pack`'s options, each declared once: flag, --config key, report parameter.
#include "pack_arguments.hpp"
#include "pak/repulsion/repulsion_presets.hpp"
#include "outline_output.hpp"
#include "shared_options.hpp"

namespace pak::cli {
namespace {

// RepulsionOptions's members, by their path in the struct.
OptionTable<RepulsionOptions> repulsionOptionTable() {
  using O = RepulsionOptions;
  using S = RepulsionStopRule;
  using P = SecondaryPassOptions;
  const OptionTable<O> elements{
      {"gap", length(&O::gap), "d_gap, the spacing between elements (canonical units: the container's bounding square is 1000 wide)"},
      {"mesh-spacing", length(&O::meshSpacing), "distance between mesh samples, canonical units (0: max(gap, element size / 10))"},
      {"count", field(&O::count), "number of elements to seed (0: container area / element area)"},
      {"element-area", field(&O::elementArea), "nominal area of one element as a fraction of the container; sets the count when --count is 0"},
      {"initial-coverage", field(&O::initialCoverage), "fraction of the container the shrunken seeds cover at the start"},
  };
  const OptionTable<O> passes{
      {"target-fill", field(&O::stop, &S::targetFill), "stop when element skins cover this fraction of the container"},
      {"stall-window", field(&O::stop, &S::stallWindow), "w of eq. 4.7, in iterations"},
      {"stall-epsilon", field(&O::stop, &S::stallEpsilon), "ε of eq. 4.7: stop when the RMS fill change per iteration falls below it"},
      {"stall-on-measured-area", field(&O::stop, &S::stallOnMeasuredArea), "apply eq. 4.7 to the measured skin area, as the thesis does, instead of the meshes' rest area"},
      {"max-iterations", field(&O::stop, &S::maxIterations), "hard cap on simulation iterations"},
      {"settle-iterations", field(&O::stop, &S::settleIterations), "the clean-up after each pass: nothing grows and every element deeper than gap/4 inside another shrinks (to 0.95 of its size, further only if its art overlaps), for at most this many iterations, until none is (0: none, as in the thesis)"},
      {"k-inversion", field(&O::simulation, &SimulationParameters::inversionStrength), "anti-inversion strength: a mesh triangle squeezed below a quarter of its rest area pushes back, so thin limbs bend instead of folding over (0: none, as in the thesis)"},
      {"self-repulsion", field(&O::simulation, &SimulationParameters::selfRepulsion), "share of k_rpl with which a far part of an element's own skin repels it, so a limb bending onto its own body does not fold over it (0: none, as in the thesis)"},
      {"k-unfold", field(&O::simulation, &SimulationParameters::unfoldStrength), "in the clean-up, an element whose art crosses itself (a limb folded over its body) is pulled toward its best-fit rest shape with this strength until it does not (0: none, as in the thesis)"},
      {"time-limit", field(&O::stop, &S::timeLimit), "stop growing after this many seconds, clean up and write the packing as it is then, with stop-reason time-limit in the report (0: no limit; a run stopped by it depends on the machine's speed). Ctrl-C does the same (interrupted); a second Ctrl-C aborts, leaving no half-written file"},
      {"secondary-scale", field(&O::secondary, &P::scale), "nominal size of a secondary element relative to a primary one (linear)"},
      {"secondary-min-distance", length(&O::secondary, &P::minDistance), "d_min: secondaries go only where the negative space is at least this far from any element or wall (canonical units; 0: max(gap, L / 4), L the nominal secondary size)"},
      {"secondary-separation", length(&O::secondary, &P::separation), "d_sep: secondary seeds keep at least this far apart (canonical units; 0: L, the nominal secondary size)"},
      {"secondary-resolution", field(&O::secondary, &P::resolution), "distance transform cells across the container for seeding secondaries"},
      {"secondary-target-fill", field(&O::secondary, &P::targetFill), "the secondary pass stops when skins (and fixed elements) cover this fraction of the container"},
      {"secondary-press", field(&O::secondary, &P::pressIterations), "after the secondary pass stops, the primaries (frozen through it) are freed and all elements are pressed into the pockets left for this many iterations before the clean-up (0: none, as in the thesis)"},
      {"shape-matching", field(&O::shapeMatching, &CornerDockingOptions::enabled), "place elements that fit the container's sharp convex corners there first and dock them (thesis 4.7)"},
      {"docking-strength", field(&O::shapeMatching, &CornerDockingOptions::dockingStrength), "with --shape-matching: spring strength holding each matched element's tip on its corner"},
      {"linear-art", field(&O::linearArt), "draw each element's art on its deformed mesh with the thesis's piecewise-linear map, as the simulation's checks do, instead of a smoothed one: the art bends a little wherever it crosses a mesh edge, and its fitted curves need about twice the points"},
      {"orientation-torsion", field(&O::orientation, &OrientationOptions::torsion), "k_tor used with --orientation upright/field when --k-torsion is 0"},
  };
  return elements + mounted(simulationOptions(), field(&O::simulation)) + passes +
         mounted(runOptions(), field(&O::run));
}

std::string presetHelp() {
  std::string help = "force strength preset, applied before --config and flags:";
  for (const RepulsionPreset& p : repulsionPresets()) help += "\n  " + p.name + ": " + p.description;
  return help;
}

// The options given as text (parsed into RepulsionOptions by the run) and the presets.
OptionTable<PackArguments> textOptionTable() {
  using A = PackArguments;
  return {
      {"preset", field(&A::preset), presetHelp()},
      {"rigid", field(&A::rigid), "nearly rigid elements (very stiff edge springs, thesis 6.4): same as --preset rigid"},
      {"tile", field(&A::tile), "pack a tileable W,H rectangle (input units) instead of a container: elements crossing an edge come back on the opposite one (thesis 4.8)"},
      {"orientation", field(&A::orientation), "preferred orientation (eq. 4.6): random (random seeded angles, no torsion unless --k-torsion), upright (seeded as drawn and held there), field (seeded at and held to --orientation-field)"},
      {"orientation-field", field(&A::orientationField), "AXIS:FROM:TO, the rest angle in degrees (clockwise on screen, as SVG rotate) turning linearly from the container's left (x) or top (y) edge to the opposite one; alone it implies --orientation field"},
      {"container-layer", field(&A::containerLayer), "the scene layer holding the containers; 'elements' makes each element of a previous Pak packing a container"},
      {"polyline", field(&A::polyline), polylineHelp(kMeshCurveTolerance)},
  };
}

}  // namespace

const OptionTable<PackArguments>& packOptions() {
  static const OptionTable<PackArguments> table =
      mounted(repulsionOptionTable(), field(&PackArguments::options)) + textOptionTable();
  return table;
}

}  // namespace pak::cli
