// `pak animate`'s options, each declared once: flag, --config key, report parameter.
#include "animate_arguments.hpp"
#include "shared_options.hpp"

namespace pak::cli {
namespace {

// AnimationOptions's members, by their path in the struct; the forces and the run's options
// are the shared tables.
OptionTable<AnimationOptions> animationOptionTable() {
  using O = AnimationOptions;
  const OptionTable<O> own{
      {"slices", field(&O::slices), "n_s, slices along t (0: the animation file's, default 100)"},
      {"time-length", field(&O::spacetime, &SpacetimeParameters::timeLength), "length of the t axis in canonical units (x and y span 1000)"},
      {"element-area", field(&O::elementArea), "an element's nominal skin area as a fraction of the container (0: 1 / element count)"},
      {"gap", field(&O::gap), "d_gap as a fraction of the nominal element size (thesis 0.08)"},
      {"mesh-spacing", length(&O::meshSpacing), "slice mesh spacing, canonical units (0: nominal element size / 4)"},
      {"initial-scale", field(&O::initialScale), "elements start shrunk to this fraction of their size (thesis 0.05–0.1)"},
      {"time-springs", field(&O::spacetime, &SpacetimeParameters::timeStrength), "time springs between consecutive slices: higher is smoother, lower packs tighter (thesis Fig. 5.21)"},
      {"target", field(&O::spacetime, &SpacetimeParameters::targetStrength), "pull of a guided element toward its targets"},
      {"temporal", field(&O::spacetime, &SpacetimeParameters::temporalStrength), "k_tmp of eq. 5.2, keeps slices at their time"},
      {"max-growth", field(&O::spacetime, &SpacetimeParameters::maxGrowth), "growth cap (1: the nominal size)"},
      {"growth-spread", field(&O::spacetime, &SpacetimeParameters::growthSpread), "a slice grows only while within this of its neighbouring slices' growth, so sizes do not pulse (0: independent slices, as in the thesis)"},
      {"growth-speed-cap", field(&O::spacetime, &SpacetimeParameters::growthSpeedCap), "a large element grows more slowly: its skin moves by at most this many velocity-cap steps per growth step, at its mean distance from the centre (0: every element at --growth-rate, as in the thesis)"},
      {"guided-growth", field(&O::spacetime, &SpacetimeParameters::guidedGrowth), "a guided element grows, pushing through the others, while smaller than this share of the unguided elements' median growth at the same moment (0: the common rule, as in the thesis)"},
      {"guided-wall-give", length(&O::spacetime, &SpacetimeParameters::guidedWallGive), "a guided element, held on its path, keeps growing to its --guided-growth share while the crowd presses it no further than this past the wall (canonical units; the frames are projected back inside)"},
      {"closeness", length(&O::stop, &AnimationStopRule::closeness), "stop when every slice is this close to a neighbour or the wall (canonical units; 0: never, the default, since a slice in contact may still grow; the thesis stops at 6, 0.006 of the container)"},
      {"stall-growth", field(&O::stop, &AnimationStopRule::stallGrowth), "stop when the slices' mean growth rose less than this over --stall-window iterations"},
      {"stall-window", field(&O::stop, &AnimationStopRule::stallWindow), "iterations over which --stall-growth is measured"},
      {"max-iterations", field(&O::stop, &AnimationStopRule::maxIterations), "stop after this many simulation steps"},
      {"settle-iterations", field(&O::stop, &AnimationStopRule::settleIterations), "after the stop (not after --time-limit or Ctrl-C, which also end it): this many more steps in which nothing grows and skins pressed into a neighbour give way with --settle-k-overlap, so the frame separation shrinks less (0: none, as in the thesis)"},
      {"settle-k-overlap", field(&O::stop, &AnimationStopRule::settleOverlapStrength), "with --settle-iterations: k_ovr (eq. 4.4) during the settle"},
      {"frame-separation", field(&O::frameSeparation, &FrameSeparationOptions::rounds), "frames between slices in which elements overlap by a sliver or leave the container: each offending element shrinks 1 % about its centre per round, for at most this many rounds, until the frame is clean, eased over neighbouring frames (0: frames as interpolated, as in the thesis)"},
      {"frame-separation-samples", field(&O::frameSeparation, &FrameSeparationOptions::samples), "frames checked for --frame-separation, evenly over t (0: twice the slices); a frame between them that still overlaps is separated on its own"},
      {"frame-separation-ramp", field(&O::frameSeparation, &FrameSeparationOptions::ramp), "with --frame-separation: an element's shrinking eases in and out over this share of the animation on either side, so it does not pulse"},
      {"frame-separation-shrink-only", field(&O::frameSeparation, &FrameSeparationOptions::shrinkOnly), "with --frame-separation: every offending element shrinks and none moves (by default an element overlapping a guided one first moves off the guided element's path, so the guided element keeps its size; see also --frame-separation-shrink-pairs)"},
      {"frame-separation-shrink-pairs", field(&O::frameSeparation, &FrameSeparationOptions::shrinkPairs), "with --frame-separation: two unguided elements that overlap shrink at once (by default they first move apart, each away from where they overlap, up to twice --frame-separation rounds of 1 % of its radius, so neither loses size)"},
      {"time-limit", field(&O::stop, &AnimationStopRule::timeLimit), "stop the simulation after this many seconds and render the animation as it is then, frames cleaned as always, with stop-reason time-limit in the report (0: no limit; a run stopped by it depends on the machine's speed). Ctrl-C does the same (interrupted); a second Ctrl-C aborts, leaving no half-written file"},
  };
  return own + mounted(simulationOptions(), field(&O::simulation)) + mounted(runOptions(), field(&O::run));
}

}  // namespace

const OptionTable<AnimateArguments>& animateOptions() {
  using A = AnimateArguments;
  static const OptionTable<A> table =
      mounted(animationOptionTable(), field(&A::options)) +
      OptionTable<A>{{"mirror", field(&A::mirror),
                      "x=VALUE: simulate the part of the container left of the vertical line x = VALUE (input units; "
                      "unlike pak flow, only a vertical line) "
                      "and show it reflected across the line too (thesis Fig. 5.18)"}};
  return table;
}

}  // namespace pak::cli
