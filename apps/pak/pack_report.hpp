#pragma once
// What `pak pack` measures on its result, and the JSON report (--report) of a run.
#include <vector>

#include <nlohmann/json.hpp>

#include "pack_arguments.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/svg_writer.hpp"
#include "pak/metrics/evenness.hpp"

namespace pak::cli {

// The result's invariants, on the art as drawn.
struct PackAudit {
  std::vector<Region> outlines;  // each element's art; a tile's with its clones, cut at the tile
  PackingCheck check;            // the fixed elements count as one more (immovable) element
  double containerArea = 0.0;
  double artArea = 0.0;          // the elements' and fixed elements' art
  Evenness evenness;             // of the negative space, as `pak metrics` measures it
  double primaryAreaSpread = 0.0;  // coefficient of variation of the primaries' art areas
};
// `library` and `secondary` are the libraries the packing was made from (for the art as drawn).
PackAudit auditPacking(const Packing& packing, const Library& library, const Library& secondary);

struct PackTimes {
  double wall = 0.0, simulation = 0.0;  // seconds
};

// `paths`: what the output SVG's paths hold (writeSvgFile).
nlohmann::json packReport(const PackArguments& args, const Scene& scene, const Packing& packing, const PackAudit& audit,
                          const PackTimes& times, const SvgPathStats& paths);

}  // namespace pak::cli
