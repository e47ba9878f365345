#include "report_fields.hpp"

namespace pak::cli {

nlohmann::json reportWithParameters(const nlohmann::json& parameters, const char* units, const GivenLengths& given) {
  // A length given with a unit: "parameters" has it in canonical units, this as written.
  return {{"parameters", parameters}, {"units", units}, {"lengths-given", given}};
}

void reportCheck(nlohmann::json& report, const PackingCheck& check) {
  report["overlap-count"] = check.overlappingPairs;
  report["overlap-area"] = check.overlapArea;
  report["elements-outside"] = check.elementsOutside;
  report["outside-area"] = check.outsideArea;
  report["self-intersecting-outlines"] = check.selfIntersecting;
  report["problems"] = check.problems;
}

nlohmann::json evennessJson(const Evenness& e) {
  return {{"resolution", e.resolution},
          {"cell", e.cell},
          {"negative-ratio", e.negativeRatio},
          {"h", e.halfWidth},
          {"P1", e.pocketShare[0]},
          {"P2", e.pocketShare[1]},
          {"P3", e.pocketShare[2]},
          {"largest-empty-radius", e.largestEmptyRadius},
          {"largest-radius-over-h", e.largestRadiusOverHalfWidth},
          {"width-spread", e.widthSpread},
          {"axis-length", e.axisLength},
          {"filled-hole-ratio", e.containerCells > 0 ? static_cast<double>(e.filledHoleCells) / e.containerCells : 0.0}};
}

}  // namespace pak::cli
