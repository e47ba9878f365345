#include "pack_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

#include "art_check.hpp"
#include "outline_output.hpp"
#include "pak/geom/closest_point.hpp"
#include "pak/metrics/packing_geometry.hpp"
#include "pak/repulsion/shape_matching.hpp"
#include "pak/repulsion/tiling.hpp"
#include "report_fields.hpp"

namespace pak::cli {
namespace {

nlohmann::json passesReport(const Packing& packing) {
  nlohmann::json passes = nlohmann::json::array();
  for (std::size_t k = 0; k < packing.passes.size(); ++k) {
    const PackingPass& pass = packing.passes[k];
    passes.push_back({{"pass", k == 0 ? "primary" : "secondary"},
                      {"elements", pass.elements},
                      {"iterations", pass.iterations},
                      {"settle-iterations", pass.settleIterations},
                      {"stop-reason", toString(pass.stopReason)},
                      {"seconds", pass.seconds},
                      {"fill-ratio-skin", pass.skinFill},
                      {"fill-ratio-art", pass.artFill}});
  }
  return passes;
}

// Thesis 4.7's salient convex corners and how close the art comes to each (canonical units),
// with or without shape matching, so runs can be compared.
void reportCorners(nlohmann::json& report, const Packing& packing, const std::vector<Region>& outlines) {
  nlohmann::json corners = nlohmann::json::array();
  double cornerSum = 0.0;
  for (const SalientCorner& c : salientContainerCorners(packing.container)) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Region& r : outlines) nearest = std::min(nearest, closestPointOnBoundary(c.position, r).distance);
    nearest *= packing.canonicalScale;
    cornerSum += nearest;
    corners.push_back({{"x", c.position.x}, {"y", c.position.y}, {"art-distance", nearest}});
  }
  report["salient-corners"] = corners;
  report["corner-art-distance-mean"] = corners.empty() ? 0.0 : cornerSum / static_cast<double>(corners.size());
}

double coefficientOfVariation(const std::vector<double>& values) {
  if (values.size() < 2) return 0.0;
  double mean = 0.0, square = 0.0;
  for (double v : values) mean += v / static_cast<double>(values.size());
  for (double v : values) square += (v - mean) * (v - mean) / static_cast<double>(values.size());
  return mean > 0.0 ? std::sqrt(square) / mean : 0.0;
}

}  // namespace

PackAudit auditPacking(const Packing& packing, const Library& library, const Library& secondary) {
  PackAudit audit;
  audit.outlines = artOutlines(packing);
  // A tile is checked on the torus: every clone's piece inside the tile, seams included.
  if (isTiled(packing.tile)) audit.outlines = periodicRepetition(audit.outlines, packing.tile, 1, 1);
  audit.containerArea = area(packing.container);
  std::vector<Region> checked = audit.outlines;
  if (!packing.fixedArt.empty()) checked.push_back(packing.fixedArt);
  std::vector<std::vector<Ring>> rest;
  for (const PlacedElement& e : packing.elements) {
    const Library& from = e.secondary ? secondary : library;
    rest.push_back(e.libraryIndex >= 0 && e.libraryIndex < static_cast<int>(from.size())
                       ? artRings(from[e.libraryIndex].shapes)
                       : std::vector<Ring>{});
  }
  audit.check = checkArt(checked, packing.container, artRings(packing), rest);
  audit.artArea = area(packing.fixedArt);
  for (const Region& r : audit.outlines) audit.artArea += area(r);
  // A tile's negative space is measured on one period, as it is drawn.
  audit.evenness = measureEvenness(packingGeometry(packing));
  std::vector<double> areas;
  for (std::size_t k = 0; k < packing.elements.size(); ++k)
    if (!packing.elements[k].secondary && !isTiled(packing.tile)) areas.push_back(area(audit.outlines[k]));
  audit.primaryAreaSpread = coefficientOfVariation(areas);
  return audit;
}

nlohmann::json packReport(const PackArguments& args, const Scene& scene, const Packing& packing, const PackAudit& audit,
                          const PackTimes& times, const SvgPathStats& paths) {
  const RepulsionOptions& options = args.options;
  nlohmann::json parameters;
  packOptions().report(parameters, args);
  parameters["threads-used"] = options.run.threads > 0 ? options.run.threads
                                                       : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  double maxEdgeStrain = 0.0, meanEdgeStrain = 0.0;
  int secondaryCount = 0;
  for (const PlacedElement& e : packing.elements) {
    maxEdgeStrain = std::max(maxEdgeStrain, e.maxEdgeStrain);
    meanEdgeStrain += e.meanEdgeStrain / static_cast<double>(packing.elements.size());
    secondaryCount += e.secondary ? 1 : 0;
  }
  nlohmann::json report =
      reportWithParameters(parameters, "distances in canonical units: the container's bounding square is 1000 wide", args.common.lengths);
  report["container"] = args.container;
  if (isTiled(packing.tile)) report["tile"] = {packing.tile.x, packing.tile.y};
  report["elements-library"] = args.elements;
  report["seed"] = options.run.seed;
  report["iterations"] = packing.iterations;
  report["stop-reason"] = toString(packing.stopReason);
  report["wall-seconds"] = times.wall;
  report["simulation-seconds"] = times.simulation;
  report["fill-ratio-art"] = audit.artArea / audit.containerArea;
  report["fill-ratio-skin"] = packing.skinFill;
  report["fill-ratios-include"] = packing.fixedArt.empty()
                                      ? "elements (art or skins) over the container area"
                                      : "elements (art or skins) and fixed elements (art, or art offset by gap/2 for skin) over the container area";
  report["preset"] = args.preset.empty() ? "default" : args.preset;
  report["secondary-library"] = args.secondary;
  report["secondary-count"] = secondaryCount;
  report["fixed-count"] = scene.fixed.size();
  report["fixed-area-ratio"] = area(packing.fixedArt) / audit.containerArea;
  report["max-edge-strain"] = maxEdgeStrain;    // over all edge springs: |length / (g × rest) − 1|
  report["mean-edge-strain"] = meanEdgeStrain;  // mean over elements of their mean
  report["passes"] = passesReport(packing);
  report["element-count"] = packing.elements.size();
  report["vertex-count"] = packing.vertexCount;
  report["spring-count"] = packing.springCount;
  reportCheck(report, audit.check);
  report["evenness"] = evennessJson(audit.evenness);
  report["primary-area-cv"] = audit.primaryAreaSpread;  // standard deviation / mean of the primaries' art areas
  report["canonical-scale"] = packing.canonicalScale;
  reportOutlines(report, args.polyline, paths, packing.canonicalScale);
  report["art-deformation"] = options.linearArt ? "linear" : "smoothed";
  report["linear-art-fallbacks"] = packing.linearArtFallbacks;  // smoothed art unclean: drawn linear
  reportElementsPerContainer(report, packing.elements, packing.containers.size());
  reportCorners(report, packing, audit.outlines);
  if (options.shapeMatching.enabled) {
    report["shape-matching"] = {{"corners", packing.salientCorners.size()},
                                {"docked-elements", packing.dockedElements},
                                {"matching-seconds", packing.shapeMatchingSeconds}};
  }
  return report;
}

}  // namespace pak::cli
