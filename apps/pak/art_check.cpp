#include "art_check.hpp"

namespace pak::cli {

PackingCheck checkArt(const std::vector<Region>& outlines, const Region& container) {
  PackingCheckOptions options;
  options.areaTolerance = 1e-6 * area(container);
  return verifyPacking(outlines, container, options);
}

}  // namespace pak::cli
