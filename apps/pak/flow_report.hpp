#pragma once
// What `pak flow` measures on its result, and the JSON report (--report) of a run.
#include <nlohmann/json.hpp>

#include "flow_arguments.hpp"
#include "pak/geom/verify.hpp"
#include "pak/io/svg_writer.hpp"

namespace pak::cli {

// The result's invariants, on the art as drawn (fixed elements count as one more element),
// and the bent elements that fold: `library` is the one packFlow was given.
PackingCheck auditFlowPacking(const FlowPacking& packing, const Library& library);

// `paths`: what the output SVG's paths hold (writeSvgFile).
nlohmann::json flowReport(const FlowArguments& args, const FlowPacking& packing, const PackingCheck& check,
                          const SvgPathStats& paths, double wallSeconds);

}  // namespace pak::cli
