#include "art_check.hpp"

namespace pak::cli {

PackingCheck checkArt(const std::vector<Region>& outlines, const Region& container,
                      const std::vector<std::vector<Ring>>& rings, const std::vector<std::vector<Ring>>& rest) {
  PackingCheckOptions options;
  options.areaTolerance = kArtAreaTolerance * area(container);
  PackingCheck check = verifyPacking(outlines, container, options);
  checkSelfIntersections(rings, check, rest);
  return check;
}

}  // namespace pak::cli
