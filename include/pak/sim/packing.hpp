#pragma once
// A finished (or in-progress) static packing: the placed elements' deformed art, skins and
// meshes in input coordinates, with the run's statistics. RepulsionPak produces one, and so
// does every frame of an AnimationPak animation, so the outputs, checks and metrics take this
// one type. Geometry and colours only: how a packing is drawn (layers, SVG attributes) is
// pak/io's business.
#include <array>
#include <string>
#include <vector>

#include "pak/geom/art.hpp"
#include "pak/geom/polygon.hpp"

namespace pak {

struct PlacedElement {
  int libraryIndex = 0;
  std::string source;       // file the element came from (its ElementArt::source)
  std::vector<Shape> art;   // deformed art in input coordinates, original paint
  Ring skin;                // deformed skin in input coordinates
  std::vector<Vec2> meshVertices;                // input coordinates
  std::vector<std::array<int, 3>> meshTriangles;
  double growth = 0.0;      // final growth factor g
  bool secondary = false;   // placed by the secondary pass; libraryIndex is then in the secondary library
  double maxEdgeStrain = 0.0;  // largest |length / (g × rest length) − 1| over its edge springs
  double meanEdgeStrain = 0.0; // mean of the same over its edge springs
  int container = 0;        // index into Packing::containers: the one it was seeded in
  // AnimationPak: it may leave the container; only its part inside is checked (checkedOutlines).
  bool leavesContainer = false;
  // AnimationPak: it follows its targets (the report gives its smallest drawn scale).
  bool guided = false;
};

// TimeLimit: the run ran out of --time-limit; Interrupted: RunOptions::stopRequest was set
// (Ctrl-C). The two stops that depend on the machine or the user.
enum class StopReason { TargetFill, Stalled, IterationCap, TimeLimit, Interrupted };
const char* toString(StopReason reason);
// Whether the clock or the user cut the run short (what follows should be quick).
inline bool stoppedEarly(StopReason reason) { return reason == StopReason::TimeLimit || reason == StopReason::Interrupted; }

// One simulation pass: the primary one, then the secondary one when it runs (4.6).
struct PackingPass {
  int elements = 0;          // elements this pass moved
  int iterations = 0;         // the clean-up's included
  StopReason stopReason = StopReason::IterationCap;
  double seconds = 0.0;      // wall time of the pass, seeding and meshing included
  double skinFill = 0.0;     // at the pass's end; as Packing::skinFill
  double artFill = 0.0;      // at the pass's end; as artFill()
  int settleIterations = 0;  // the clean-up's (RepulsionStopRule::settleIterations)
};

struct Packing {
  std::vector<PlacedElement> elements;
  Region container;              // input coordinates
  std::vector<Region> containers;  // the separate containers (parts of `container`), input coordinates
  double canonicalScale = 1.0;   // canonical units per input unit
  int iterations = 0;
  StopReason stopReason = StopReason::IterationCap;
  double skinFill = 0.0;         // (skin area + area blocked by fixed elements) / container area
  std::vector<PackingPass> passes;
  // Fixed elements (Scene::fixed): what they paint inside the container, input coordinates.
  Region fixedArt;
  int vertexCount = 0;
  int springCount = 0;
  // Shape matching (empty / 0 when off): the salient corners (input coordinates), how many
  // elements were docked at them, and the matching stage's time.
  std::vector<Vec2> salientCorners;
  int dockedElements = 0;
  double shapeMatchingSeconds = 0.0;
  Vec2 tile{};                   // W × H of a tileable packing (input units); 0: not tiled
  // Elements drawn with the linear map although the smoothed one was asked for: theirs
  // overlapped, left the container or crossed itself (RepulsionOptions::linearArt).
  int linearArtFallbacks = 0;
};

// What one element's art paints, as one region (the union of its shapes), and the same for
// each placed element.
Region artOutline(const std::vector<Shape>& art);
std::vector<Region> artOutlines(const Packing& packing);
// Each placed element's filled rings as drawn (its filled shapes' subpaths; strokes are
// bands, not outlines), for checkSelfIntersections.
std::vector<std::vector<Ring>> artRings(const Packing& packing);
std::vector<Ring> artRings(const std::vector<Shape>& art);
// Total painted area of the elements and the fixed elements over the container area.
double artFill(const Packing& packing);

}  // namespace pak
