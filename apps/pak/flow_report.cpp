#include "flow_report.hpp"

#include "outline_output.hpp"

#include "art_check.hpp"
#include "report_fields.hpp"
#include "pak/sim/packing.hpp"

namespace pak::cli {

PackingCheck auditFlowPacking(const FlowPacking& packing, const Library& library) {
  std::vector<Region> outlines;
  // Folds: a bent element's art rings that cross themselves where the drawn ones do not.
  std::vector<std::vector<Ring>> rings, rest;
  for (const auto* list : {&packing.elements, &packing.gapElements})
    for (const FlowElement& e : *list) {
      outlines.push_back(e.outline);
      rings.push_back(artRings(e.art));
      const bool drawn = e.libraryIndex >= 0 && e.libraryIndex < static_cast<int>(library.size());
      rest.push_back(drawn ? artRings(library[static_cast<std::size_t>(e.libraryIndex)].shapes) : std::vector<Ring>{});
    }
  if (!packing.fixedArt.empty()) outlines.push_back(packing.fixedArt);
  return checkArt(outlines, packing.container, rings, rest);
}

nlohmann::json flowReport(const FlowArguments& args, const FlowPacking& packing, const PackingCheck& check,
                          const SvgPathStats& paths, double wallSeconds) {
  nlohmann::json parameters;
  flowOptions().report(parameters, args);
  nlohmann::json report =
      reportWithParameters(parameters, "distances in canonical units: l_canvas (the larger side of the containers' and fixed elements' bounds) is 1000", args.common.lengths);
  report["scene"] = args.scene;
  report["elements-library"] = args.elements;
  report["element-count"] = packing.elements.size();
  report["gap-element-count"] = packing.gapElements.size();
  report["streamline-count"] = packing.streamlines.size();
  report["infill-element-count"] = packing.infilled;  // of element-count: added in pockets (--infill-every)
  report["iterations"] = packing.iterations;
  report["stop-reason"] = toString(packing.stopReason);
  report["placements-tried"] = packing.placementsTried;
  report["placements-accepted"] = packing.placementsAccepted;
  report["fill-ratio-art"] = flowFill(packing);
  report["fill-ratio-includes"] = "placed elements (and gap shapes) over the free space (containers minus fixed elements)";
  report["element-area-per-iteration"] = packing.areaPerIteration;
  report["seconds"] = {{"field", packing.seconds.field},           {"streamlines", packing.seconds.streamlines},
                       {"blobs", packing.seconds.blobs},           {"placement", packing.seconds.placement},
                       {"refinement", packing.seconds.refinement}, {"extras", packing.seconds.extras},
                       {"wall", wallSeconds}};
  reportCheck(report, check);
  reportOutlines(report, args.polyline, paths, packing.canonicalScale);
  report["canonical-scale"] = packing.canonicalScale;
  // The density used (the options', or worked out when left automatic), canonical units.
  report["density"] = {{"gap", packing.density.gap},
                       {"min-length", packing.density.minLength},
                       {"max-length", packing.density.maxLength},
                       {"spacing", packing.density.spacing}};
  reportElementsPerContainer(report, packing.elements, packing.containers.size());
  return report;
}

}  // namespace pak::cli
