#include "report_fields.hpp"

namespace pak::cli {

nlohmann::json reportWithParameters(const nlohmann::json& parameters, const char* units) {
  return {{"parameters", parameters}, {"units", units}};
}

void reportCheck(nlohmann::json& report, const PackingCheck& check) {
  report["overlap-count"] = check.overlappingPairs;
  report["overlap-area"] = check.overlapArea;
  report["elements-outside"] = check.elementsOutside;
  report["outside-area"] = check.outsideArea;
  report["problems"] = check.problems;
}

}  // namespace pak::cli
