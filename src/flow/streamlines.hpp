#pragma once
// Evenly spaced streamlines (thesis 3.3.3, Algorithm 1, after Jobard & Lefer [JL97]).
#include <cstdint>
#include <vector>

#include "pak/flow/vector_field.hpp"
#include "pak/geom/polygon.hpp"

namespace pak {

struct StreamlineOptions {
  double gap = 10.0;          // s_gap: desired distance between neighbouring streamlines
  double stopRatio = 0.8;     // s_stop = stopRatio * s_gap
  double minLength = 20.0;    // s_min: shorter streamlines are discarded
  double maxLength = 100.0;   // s_max: tracing stops before exceeding it
  double sampleSpacing = 1.0; // seeds on boundary/guides and along streamlines (0.005 l_canvas)
  double step = 0.0;          // integration step; 0 means sampleSpacing / 2
  std::uint64_t seed = 1;     // orders equally distant seeds
};

struct StreamlineInput {
  Region container;                      // the region to fill (holes allowed)
  Region obstacles;                      // fixed elements: streamlines stop at them
  std::vector<Polyline> guides;          // seeds are taken on them (and on the boundary)
  std::vector<Polyline> fixedStreamlines;  // fixed spines: count as traced streamlines for s_stop
};

// Streamlines in tracing order; each lies inside the container, outside the obstacles, is
// between s_min and s_max long and keeps at least s_stop from every other streamline
// (fixed ones included). Deterministic for a seed.
std::vector<Polyline> traceStreamlines(const VectorField& field, const StreamlineInput& input,
                                       const StreamlineOptions& options);

}  // namespace pak
