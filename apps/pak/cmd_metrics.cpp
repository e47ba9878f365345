// `pak metrics PACKING.svg…`: how even the negative space of packings is (thesis chapter 6,
// and the evenness measure of the RepulsionPak quality issue): tables on stdout, every curve
// and figure as CSV/JSON, a comparison figure, offset and distance images.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/io/output_batch.hpp"
#include "pak/io/atomic_file.hpp"
#include "pak/io/distance_map_image.hpp"
#include "pak/io/evenness_map_image.hpp"
#include "pak/io/json_syntax_error.hpp"
#include "pak/io/metrics_plot.hpp"
#include "pak/io/offset_visualization.hpp"
#include "pak/io/packing_reader.hpp"
#include "pak/io/text_file.hpp"
#include "pak/metrics/evenness.hpp"
#include "output_files.hpp"
#include "report_fields.hpp"
#include "pak/metrics/metrics.hpp"

namespace pak::cli {
namespace {

using nlohmann::json;

struct MetricsArgs {
  std::vector<std::string> files;
  std::optional<double> gap;
  std::string report;
  MetricsOptions metrics;
  bool calibrate = false;
  PackingReadOptions layers;
  std::string csv, json, plot;
  std::optional<double> visualize;
  std::string visualizeOut;
  std::string distanceMap;
  std::string evennessMap;
};

// One packing's chapter-6 metrics and its evenness, measured on the same geometry.
struct Measured {
  PackingMetrics metrics;
  Evenness evenness;
};

std::string extensionOf(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

// d_gap in the packing's units from a Pak report: an explicit "d_gap", else the canonical
// gap of `pak pack` divided by the canonical units per input unit.
double gapFromReport(const std::string& path) {
  json report;
  try {
    report = json::parse(readTextFile(path));
  } catch (const json::exception& error) {
    throw jsonSyntaxError(path, error.what());
  }
  if (!report.is_object()) throw InputError(path, "the report is not a JSON object");
  if (report.contains("d_gap") && report["d_gap"].is_number()) return report["d_gap"].get<double>();
  const json* gap = report.contains("parameters") && report["parameters"].is_object() &&
                            report["parameters"].contains("gap")
                        ? &report["parameters"]["gap"]
                        : nullptr;
  if (!gap || !gap->is_number() || !report.contains("canonical-scale") || !report["canonical-scale"].is_number())
    throw InputError(path, "the report has neither \"d_gap\" nor \"parameters\".\"gap\" with \"canonical-scale\"");
  double scale = report["canonical-scale"].get<double>();
  if (!(scale > 0.0) || !std::isfinite(scale)) throw InputError(path, "\"canonical-scale\" must be positive");
  return gap->get<double>() / scale;
}

double negativeRatio(const PackingGeometry& packing) {
  double inside = area(intersect(unite(packing.elements), packing.container));
  return 1.0 - inside / area(packing.container);
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string general(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

json curveJson(const Curve& curve) { return {{"r", curve.r}, {"value", curve.value}}; }


json packingJson(const Measured& measured, const std::optional<double>& offset) {
  const PackingMetrics& m = measured.metrics;
  json out = {{"file", m.source},
              {"elements", m.elementCount},
              {"container-area", m.containerArea},
              {"positive-ratio", m.positiveRatio},
              {"negative-ratio", m.negativeRatio},
              {"d_gap", m.gap},
              {"d_gap-estimated", m.gapEstimated},
              {"Q-half-gap", m.contactAtHalfGap},
              {"O-half-gap", m.overlapAtHalfGap},
              {"largest-empty-radius", m.largestEmptyRadius},
              {"curves",
               {{"Q", curveJson(m.sphericalContact)},
                {"H", curveJson(m.distanceHistogram)},
                {"O", curveJson(m.overlap)},
                {"Q-grid", curveJson(m.gridSphericalContact)}}},
              {"histogram", {{"edges", m.binEdges}, {"density", m.binDensity}}}};
  out["calibration-offset"] = offset ? json(*offset) : json(nullptr);
  out["evenness"] = evennessJson(measured.evenness);
  return out;
}

// Long format: one row per sample, so any tool can pivot it. The evenness adds the curve P
// (r = k, value P_k) and rows of single figures with an empty r.
std::string csvText(const std::vector<Measured>& all) {
  std::ostringstream out;
  out.precision(10);
  out << "file,curve,r,value\n";
  auto quoted = [](const std::string& text) {
    std::string q = "\"";
    for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  for (const Measured& measured : all) {
    const PackingMetrics& m = measured.metrics;
    auto rows = [&](const char* name, const Curve& curve) {
      for (std::size_t i = 0; i < curve.r.size() && i < curve.value.size(); ++i)
        out << quoted(m.source) << "," << name << "," << curve.r[i] << "," << curve.value[i] << "\n";
    };
    rows("Q", m.sphericalContact);
    rows("H", m.distanceHistogram);
    rows("O", m.overlap);
    rows("Q-grid", m.gridSphericalContact);
    // Histogram bins by their left edge.
    for (std::size_t i = 0; i + 1 < m.binEdges.size() && i < m.binDensity.size(); ++i)
      out << quoted(m.source) << ",histogram," << m.binEdges[i] << "," << m.binDensity[i] << "\n";
    const Evenness& e = measured.evenness;
    for (int k = 1; k <= 3; ++k) out << quoted(m.source) << ",P," << k << "," << e.pocketShare[k - 1] << "\n";
    const std::pair<const char*, double> figures[] = {{"evenness-negative-ratio", e.negativeRatio},
                                                      {"evenness-h", e.halfWidth},
                                                      {"evenness-largest-radius-over-h", e.largestRadiusOverHalfWidth},
                                                      {"evenness-width-spread", e.widthSpread}};
    for (const auto& [name, value] : figures) out << quoted(m.source) << "," << name << ",," << value << "\n";
  }
  return out.str();
}

// Columns padded to their widest cell: file names left-aligned, numbers right-aligned.
std::string alignedRows(const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> widths;
  for (const auto& row : rows) {
    widths.resize(std::max(widths.size(), row.size()), 0);
    for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
  }
  std::ostringstream out;
  for (const auto& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      const std::string& cell = row[c];
      std::string pad(widths[c] - cell.size(), ' ');
      out << (c ? "  " : "") << (c == 0 ? cell + (c + 1 < row.size() ? pad : "") : pad + cell);
    }
    out << "\n";
  }
  return out.str();
}

std::string tableText(const std::vector<Measured>& all, const std::vector<std::optional<double>>& offsets,
                      bool calibrated) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> header = {"file", "elements", "positive", "negative", "d_gap", "Q(d_gap/2)", "O(d_gap/2)",
                                     "largest empty r"};
  if (calibrated) header.push_back("offset");
  rows.push_back(header);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const PackingMetrics& m = all[i].metrics;
    std::vector<std::string> row = {m.source,
                                    std::to_string(m.elementCount),
                                    fixed(100.0 * m.positiveRatio, 2) + "%",
                                    fixed(100.0 * m.negativeRatio, 2) + "%",
                                    general(m.gap) + (m.gapEstimated ? " (est.)" : ""),
                                    fixed(m.contactAtHalfGap, 5),
                                    fixed(m.overlapAtHalfGap, 5),
                                    general(m.largestEmptyRadius)};
    if (calibrated) row.push_back(offsets[i] ? general(*offsets[i]) : "-");
    rows.push_back(row);
  }
  return alignedRows(rows);
}

// The evenness measure's own table: its negative space is the grid's, with small holes filled
// and fixed art counted as positive, so it may differ from the exact one above.
std::string evennessTableText(const std::vector<Measured>& all) {
  std::vector<std::vector<std::string>> rows = {
      {"file", "negative", "h", "P1 (D>h)", "P2 (D>2h)", "P3 (D>3h)", "largest r/h", "width spread"}};
  for (const Measured& measured : all) {
    const Evenness& e = measured.evenness;
    rows.push_back({measured.metrics.source, fixed(100.0 * e.negativeRatio, 2) + "%", general(e.halfWidth),
                    fixed(e.pocketShare[0], 4), fixed(e.pocketShare[1], 4), fixed(e.pocketShare[2], 4),
                    fixed(e.largestRadiusOverHalfWidth, 2), fixed(e.widthSpread, 3)});
  }
  const int resolution = all.empty() ? 0 : all.front().evenness.resolution;
  return "\nEvenness on a " + std::to_string(resolution) + "-cell grid (h: median distance to the nearest element "
         "or wall along the medial axis of the negative space):\n" + alignedRows(rows);
}

// Several packings share one --visualize-out name: number them before the extension.
std::string visualizationPath(const std::string& base, std::size_t index, std::size_t count) {
  if (count == 1) return base;
  std::filesystem::path path(base);
  return (path.parent_path() / (path.stem().string() + "-" + std::to_string(index + 1) + path.extension().string()))
      .string();
}

int runMetrics(MetricsArgs& args, const CLI::App&) {
  // Check the outputs before the (slow) measuring, so a typo fails at once.
  if (!args.plot.empty() && extensionOf(args.plot) != ".png" && extensionOf(args.plot) != ".svg")
    throw InputError(args.plot, "unknown plot format '" + extensionOf(args.plot) + "' (use .png or .svg)");
  if (args.visualize.has_value() != !args.visualizeOut.empty())
    throw InputError("--visualize", "R and --visualize-out FILE.png go together");
  if (args.visualize && (!std::isfinite(*args.visualize) || *args.visualize < 0.0))
    throw InputError("--visualize", "must be a non-negative offset");
  if (!args.visualizeOut.empty() && extensionOf(args.visualizeOut) != ".png")
    throw InputError(args.visualizeOut, "--visualize-out must be a .png file");
  if (!args.distanceMap.empty() && extensionOf(args.distanceMap) != ".png")
    throw InputError(args.distanceMap, "--distance-map must be a .png file");
  if (!args.evennessMap.empty() && extensionOf(args.evennessMap) != ".png")
    throw InputError(args.evennessMap, "--evenness-map must be a .png file");

  // Every file it will write, as numbered for several packings: none may be a packing it
  // reads (`--json` onto the packing replaced it), the report, or another output.
  std::vector<PlannedOutput> outputs{{"--csv", args.csv}, {"--json", args.json}, {"--plot", args.plot}};
  const std::size_t count = args.files.size();
  for (auto [option, path] : {std::pair{"--visualize-out", &args.visualizeOut}, std::pair{"--distance-map", &args.distanceMap},
                              std::pair{"--evenness-map", &args.evennessMap}})
    if (!path->empty())
      for (std::size_t i = 0; i < count; ++i) outputs.push_back({option, visualizationPath(*path, i, count)});
  std::vector<std::string> inputs = args.files;
  inputs.push_back(args.report);
  checkOutputsBeforeTheRun(outputs, inputs);

  if (args.gap) args.metrics.gap = *args.gap;
  else if (!args.report.empty()) args.metrics.gap = gapFromReport(args.report);

  std::vector<PackingGeometry> packings;
  for (const std::string& file : args.files) packings.push_back(readPacking(file, args.layers));
  // An offset wider than the container covers all of it, and a huge one overflows the clipper.
  if (args.visualize)
    for (const PackingGeometry& p : packings) {
      Box box;
      for (const Polygon& poly : p.container) box.add(bounds(poly));
      const double side = std::max(box.width(), box.height());
      if (*args.visualize > side) throw InputError("--visualize", "must be 0 to the container's size, " + messageNumber(side));
    }

  // Thesis 6.4: compare at the same negative-space ratio, here the packings' mean.
  std::vector<std::optional<double>> offsets(packings.size());
  if (args.calibrate) {
    double mean = 0.0;
    for (const PackingGeometry& p : packings) mean += negativeRatio(p);
    mean /= static_cast<double>(packings.size());
    for (std::size_t i = 0; i < packings.size(); ++i) {
      Calibration calibration = calibrateNegativeSpace(packings[i], mean);
      offsets[i] = calibration.offset;
      packings[i] = std::move(calibration.calibrated);
    }
  }

  // --grid is the evenness grid too: both rasterize the container's bounding square.
  EvennessOptions evenness;
  evenness.resolution = args.metrics.gridResolution;
  std::vector<Measured> measured;
  for (const PackingGeometry& p : packings) measured.push_back({measurePacking(p, args.metrics), measureEvenness(p, evenness)});

  OutputBatch batch;  // every output, or none
  if (!args.csv.empty()) writeFileAtomically(args.csv, csvText(measured));
  if (!args.json.empty()) {
    json list = json::array();
    for (std::size_t i = 0; i < measured.size(); ++i) list.push_back(packingJson(measured[i], offsets[i]));
    writeFileAtomically(args.json, json{{"packings", list}}.dump(2) + "\n");
  }
  if (!args.plot.empty()) {
    std::vector<PackingMetrics> curves;
    for (const Measured& m : measured) curves.push_back(m.metrics);
    writeMetricsPlot(curves, args.plot);
  }
  if (args.visualize)
    for (std::size_t i = 0; i < packings.size(); ++i)
      writeOffsetVisualization(packings[i], *args.visualize, visualizationPath(args.visualizeOut, i, packings.size()));
  if (!args.distanceMap.empty())
    for (std::size_t i = 0; i < packings.size(); ++i)
      writeDistanceMapImage(packings[i], visualizationPath(args.distanceMap, i, packings.size()),
                            args.metrics.gridResolution);
  if (!args.evennessMap.empty())
    for (std::size_t i = 0; i < packings.size(); ++i)
      writeEvennessMapImage(packings[i], visualizationPath(args.evennessMap, i, packings.size()), evenness);

  batch.commit();
  std::cout << tableText(measured, offsets, args.calibrate) << evennessTableText(measured) << std::flush;
  return 0;
}

void declareMetricsOptions(CLI::App& command, MetricsArgs& args) {
  command.add_option("files", args.files, "Packing SVG files to measure and compare")->required()->type_name("PACKING");
  command.add_option("--gap", args.gap, "d_gap in the file's units (default: from --report, else estimated)")
      ->type_name("D");
  command.add_option("--report", args.report,
                     "Pak report (pak pack --report) to read d_gap from: \"d_gap\", or \"parameters\".\"gap\" / "
                     "\"canonical-scale\"")
      ->type_name("FILE");
  command.add_option("--radii", args.metrics.radii, "samples of r for Q, H and O (default: 100)")->type_name("N");
  command.add_option("--grid", args.metrics.gridResolution,
                     "distance-transform grid cells along the container's bounding square, for the histogram, "
                     "the distance map and the evenness measure (default: 1000)")
      ->type_name("N");
  command.add_option("--bins", args.metrics.histogramBins, "bins of the discrete distance histogram (default: 50)")
      ->type_name("N");
  command.add_option("--arc-tolerance", args.metrics.arcTolerance,
                     "largest error of the polygon offsets and of the outline simplification before them, "
                     "in the file's units (default 0: 1e-4 of the container's bounding square)")
      ->type_name("D");
  command.add_flag("--calibrate", args.calibrate,
                   "offset every packing's elements uniformly to the packings' mean negative-space ratio first "
                   "(thesis 6.4), and report the offset");
  command.add_option("--container-layer", args.layers.containerLayer, "layer holding the container (default: container)")
      ->type_name("NAME");
  command.add_option("--elements-layer", args.layers.elementsLayer,
                     "layer whose child groups are the elements (default: elements)")
      ->type_name("NAME");
  command.add_option("--fixed-layer", args.layers.fixedLayer,
                     "layer of fixed elements, positive space for the evenness measure (default: fixed)")
      ->type_name("NAME");
  command.add_option("--csv", args.csv, "write every curve as CSV (file,curve,r,value)")->type_name("FILE");
  command.add_option("--json", args.json, "write every quantity and curve as JSON")->type_name("FILE");
  command.add_option("--plot", args.plot, "draw Q, H and O of all packings side by side (.png or .svg)")
      ->type_name("FILE");
  command.add_option("--visualize", args.visualize,
                     "draw elements offset by R with overlaps in red (thesis Fig. 6.4); needs --visualize-out")
      ->type_name("R");
  command.add_option("--visualize-out", args.visualizeOut,
                     "PNG for --visualize (numbered -1, -2 … for several packings)")
      ->type_name("FILE.png");
  command.add_option("--distance-map", args.distanceMap,
                     "draw the distance transform of the negative space, one pixel per grid cell, light = far "
                     "from any element (thesis Fig. 6.3b; numbered -1, -2 … for several packings)")
      ->type_name("FILE.png");
  command.add_option("--evenness-map", args.evennessMap,
                     "draw the evenness measure, one pixel per grid cell: channels blue by distance, pockets "
                     "D > 2h orange and D > 3h red, the medial axis white, filled small holes dark grey "
                     "(numbered -1, -2 … for several packings)")
      ->type_name("FILE.png");
}

const CommandRegistrar registrar{subcommand<MetricsArgs>(
    "metrics",
    "Measure how even the negative space of packings is (thesis chapter 6): positive/negative "
    "space ratios, the spherical contact probability Q(r), the distance histogram H(r) = -Q'(r), "
    "the overlap function O(r), and Q and O at d_gap/2; and the evenness measure: h, the median distance "
    "to the nearest element or wall along the medial axis of the negative space, and the pocket shares "
    "P_k, the fraction of the negative space farther than k h from everything (docs/metrics.md). Reads "
    "Pak's output (layers `container`, `elements` and `fixed`), other layer names, or else takes the "
    "largest closed shape as the container "
    "and each top-level group or shape as an element. Lengths are in the file's own units.",
    declareMetricsOptions, runMetrics)};

}  // namespace
}  // namespace pak::cli
