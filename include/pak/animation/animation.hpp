#pragma once
// AnimationPak (thesis chapter 5): pack animated elements into a static container.
//
//   AnimatedPacking a = packAnimation(scene, library, script, options);
//   Packing frame = animationFrame(a, 0.25);   // any t ∈ [0, 1]: a static packing
//
// `library[i]` is the art of `script.elements[i]`. Like RepulsionPak, the container's bounding
// square maps to a canonical 1000 × 1000 frame and the time axis to [0, timeLength] there.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pak/animation/animation_options.hpp"
#include "pak/animation/animation_script.hpp"
#include "pak/geom/scene.hpp"
#include "pak/geom/vec3.hpp"
#include "pak/geom/verify.hpp"
#include "pak/sim/element_mesh.hpp"
#include "pak/sim/packing.hpp"

namespace pak {

// Everything a checkpoint holds; the rest is rebuilt from the same inputs.
struct AnimationState {
  int iteration = 0;
  std::vector<Vec3> positions, velocities;
  std::vector<double> growth;
  std::vector<double> previousGrowth;  // each slice's g before the last step's growth
  // Where the vertices were when the neighbour lists were last built: a resumed run builds
  // the same lists, so it goes on bit-identically.
  std::vector<Vec3> neighbourOrigin;
  // The stopping rule's memory: mean growth of recent iterations (a ring indexed by
  // iteration) and how many iterations it has seen.
  std::vector<double> recentMeanGrowth;
  int recorded = 0;
};

struct AnimationProgress {
  int iteration = 0;
  double fill = 0.0;             // mean over slices of the skins' area / container area
  int growingSlices = 0, overlappingSlices = 0, slices = 0;
  double largestSliceGap = 0.0;  // canonical units
  double minGrowth = 0.0;
  double growthRise = 0.0;        // mean growth's rise over the stall window (∞ until it is full)
  int settleLeft = -1;            // in the settle after the stop: its steps still to come
};

struct AnimationCallbacks {
  std::function<void(const AnimationProgress&)> onProgress;
  int progressEvery = 50;
  std::function<void(const AnimationState&)> onCheckpoint;
  int checkpointEvery = 0;       // 0: never
};

enum class AnimationStop { AllTouching, GrowthCap, Stalled, IterationCap, TimeLimit, Interrupted };
const char* toString(AnimationStop reason);

struct AnimatedElement {
  std::string id;                // the script element it copies
  std::string source;            // its SVG
  int copy = 0;                  // which of the script element's `count` copies
  bool guided = false;
  bool leavesContainer = false;  // AnimatedElementSpec::leavesContainer
  // Where its loop takes it (input units): a frame at t shows it also moved by ± this, so a
  // bird that leaves on the right comes back on the left and frames side by side tile.
  Vec2 loopShift;
  ElementMesh mesh;              // slice mesh with the art's barycentric bindings
  std::vector<Shape> art;        // the art the bindings replay (paint kept)
  double restSkinArea = 0.0;     // canonical units², at growth 1
  std::vector<double> sliceTimes;            // t ∈ [0, 1] of each slice
  std::vector<std::vector<Vec2>> slices;     // each slice's mesh vertices, input coordinates
  std::vector<double> sliceGrowth;           // g of each slice
  // Frame separation: its scale, and its shift (input units, applied after the scale), at
  // AnimatedPacking::separationTimes (empty: none).
  std::vector<double> separationScale;
  std::vector<Vec2> separationShift;
};

struct AnimatedPacking {
  std::vector<AnimatedElement> elements;
  Region container;              // input coordinates
  Region fixedArt;               // input: the fixed elements' art inside the container (obstacles)
  double canonicalScale = 1.0;   // canonical units per input unit
  int iterations = 0;            // the settle's included
  int settleIterations = 0;      // the settle's (AnimationStopRule::settleIterations)
  AnimationStop stopReason = AnimationStop::IterationCap;
  double fill = 0.0;             // mean skin fill over slices at the end
  int overlappingSlices = 0;     // slices overlapping another element at the end
  int unfoldedSlices = 0;        // slices relaxed toward their rest shape: their art, or a frame between two, folded
  std::size_t vertices = 0, springs = 0, envelopeTriangles = 0;
  int slices = 0;
  double seconds = 0.0;          // set up and simulation
  double setupSeconds = 0.0;
  double separationSeconds = 0.0;  // of `seconds`: the frame separation (separateAnimation)
  int threads = 1;
  std::uint64_t seed = 1;
  bool loop = false;             // the script loops: t = 1 is t = 0
  // AnimationOptions::mirrorX: the elements were packed left of this line, and every frame
  // shows them reflected across it too (the container is the whole one).
  std::optional<double> mirrorX;
  std::vector<double> separationTimes;  // ascending t of the frame separation's samples
};

// What the animation simulates: the scene, or with a mirror its container's part left of the
// line (InputError when there is none).
Scene simulatedPart(const Scene& scene, const AnimationOptions& options);

AnimatedPacking packAnimation(const Scene& scene, const Library& library, const AnimationScript& script,
                              const AnimationOptions& options = {}, const AnimationCallbacks& callbacks = {},
                              const AnimationState* resumeFrom = nullptr);

// The packing at time t ∈ [0, 1]: each element's mesh interpolated between the two slices
// around t and its art replayed on it (thesis 5.6). After the elements come the copies of
// travelling ones (AnimatedElement::loopShift), then, with a mirror, every one reflected. A static Packing, so every RepulsionPak
// output (SVG, PNG, verifyPacking, metrics) works on a frame.
Packing animationFrame(const AnimatedPacking& animation, double t);

// The smallest, over guided elements and slice indices, of a guided slice's growth g over the
// median g of the unguided elements' slices of the same index: how small guided elements come
// out. 1 when there is no guided or no unguided element.
double smallestGuidedGrowthRatio(const AnimatedPacking& animation);

// How frantically the elements move (thesis Fig. 5.21): the mean, over the unguided elements
// and `frames` frames evenly spaced in t (as pak animate renders them), of the length of the
// centroid's second difference c(i − 1) − 2 c(i) + c(i + 1), in canonical units per frame².
// A loop wraps around. Scripted translations count too; guided elements, whose path is
// scripted, are left out. 0 with fewer than 3 frames.
double meanCentroidAcceleration(const AnimatedPacking& animation, int frames);

// Frame separation (FrameSeparationOptions, docs/animationpak.md), done by packAnimation:
// frames at `samples` evenly spaced t are separated, and each element's shrinking is eased
// over `ramp` of t on either side; animationFrame applies the result at any t.
void separateAnimation(AnimatedPacking& animation, const FrameSeparationOptions& options, int threads = 1);
// What a frame's check sees: the elements' art outlines (of one that may leave the container,
// its part inside), then the fixed art (an obstacle) as one more outline when there is any.
std::vector<Region> checkedOutlines(const Packing& frame);
// One frame's separation, the safety net at t between the samples: each offending element
// shrinks a step per round until the frame is clean; an unguided element of an overlapping
// pair first moves away from the overlap (FrameSeparationOptions::shrinkOnly, shrinkPairs). Returns the smallest scale it
// gave an element (1: the frame was clean, or rounds = 0); `scales` and `shifts`, when given,
// get every element's; `check`, when given, gets the verifyPacking of the frame as returned if
// the last round made one (it did unless rounds = 0 or the rounds ran out), so a caller need
// not check it again.
double separateFrame(Packing& frame, const FrameSeparationOptions& options, std::vector<double>* scales = nullptr,
                     std::optional<PackingCheck>* check = nullptr, std::vector<Vec2>* shifts = nullptr);
// Element e's scale at t from the animation's separation (eased between its samples; 1 when
// it has none): animationFrame applies it, and a frame's own separation comes on top.
double separationScaleAt(const AnimatedPacking& animation, std::size_t e, double t);
// The same for its shift ({0, 0} when it has none).
Vec2 separationShiftAt(const AnimatedPacking& animation, std::size_t e, double t);

}  // namespace pak
