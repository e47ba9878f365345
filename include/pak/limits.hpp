#pragma once
// The bounds on every size an option sets, in one place: what keeps a run's memory and time
// sane whatever is typed. Each is far from any useful value; the checks that use them name
// the option (`--cell-size: must be …`). Lengths are canonical units (the container's
// bounding square is 1000 wide).
namespace pak::limits {

// Worker threads beyond this many per core only add switching, and 10,000 exhaust the process.
constexpr int kThreadsPerCore = 4;

// Neighbour grid cells: the grid over the 1000-wide frame has (1000 / cell)² cells.
constexpr double kMinCellSize = 1.0;
constexpr double kMaxCellSize = 1000.0;

// Mesh samples: an element's vertex count grows with (size / spacing)².
constexpr double kMinMeshSpacing = 2.0;

// AnimationPak's spacetime grid: (1000 / cell)² × (time length / cell) cells, a few dozen
// bytes each; the default (cell 40, time length 1000) has 16,000.
constexpr double kMaxSpacetimeCells = 4e6;
constexpr double kMaxTimeLength = 10000.0;

// AnimationPak's counts: frames rendered (--frames, --svg-keyframes, --evenness-frames and the
// animation file's "frames"), slices simulated, copies of one element.
constexpr int kMaxFrames = 10000;
constexpr int kMaxSlices = 1000;
constexpr int kMaxElementCopies = 10000;
// The animation file's numbers: far beyond any animation, small enough that the geometry
// built from them stays finite and the grids small (a rotation of 1e308 degrees has no
// meaningful angle; a translation of 1e9 leaves every container).
constexpr double kMaxDegrees = 36000.0;            // a hundred turns over one loop
constexpr double kMaxAnimationScale = 1000.0;
constexpr double kMaxAnimationCoordinate = 1e6;    // translations, handles and targets, in file units
constexpr double kMaxLoopSeconds = 86400.0;        // one day per loop

// Δt: steps beyond this throw elements far outside the frame in one step (thesis: 0.1).
constexpr double kMaxTimeStep = 10.0;

// FLOWPAK: streamlines and guides are sampled every --sample-spacing (thesis: 5), and
// streamlines lie about --gap apart: their counts grow as 1000 / each.
constexpr double kMinSampleSpacing = 0.5;
constexpr double kMinFlowGap = 1.0;

// pak metrics: the distance grid has resolution² cells, and each radius sample offsets every
// element once.
constexpr int kMaxGridResolution = 4000;
constexpr int kMaxRadii = 1000;
constexpr int kMaxHistogramBins = 10000;
// An offset's arc tolerance, as a share of the offset distance (in clipping) or of the
// container's bounding square (metrics --arc-tolerance): about π / √(2 · share) points a
// turn, 22,000 here; 1e-12 made arcs of millions of points (5.4 GB).
constexpr double kMinArcToleranceShare = 1e-8;

}  // namespace pak::limits
