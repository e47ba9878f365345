#pragma once
// What `pak flow` measures on its result, and the JSON report (--report) of a run.
#include <nlohmann/json.hpp>

#include "flow_arguments.hpp"
#include "pak/geom/verify.hpp"

namespace pak::cli {

// The result's invariants, on the art as drawn (fixed elements count as one more element),
// and the bent elements that fold: `library` is the one packFlow was given.
PackingCheck auditFlowPacking(const FlowPacking& packing, const Library& library);

nlohmann::json flowReport(const FlowArguments& args, const FlowPacking& packing, const PackingCheck& check,
                          double wallSeconds);

}  // namespace pak::cli
