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
#include "metrics_measure.hpp"
#include "metrics_resolve.hpp"
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

using Measured = MeasuredPacking;

std::string extensionOf(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
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

std::string tableText(const std::vector<Measured>& all, bool calibrated) {
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
    if (calibrated) row.push_back(all[i].calibrationOffset ? general(*all[i].calibrationOffset) : "-");
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

int runMetrics(MetricsArguments& args, const CLI::App& command) {
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
  inputs.push_back(args.config);
  checkOutputsBeforeTheRun(outputs, inputs);

  nlohmann::json config;
  if (!args.config.empty()) config = readConfigObject(args.config);
  const bool gapGiven = resolveMetricsOptions(args, command, args.config.empty() ? nullptr : &config, args.config);
  // A gap given wins over the report's, which is not read then.
  if (!gapGiven && !args.report.empty()) args.metrics.gap = gapFromReport(readReportFile(args.report), args.report);

  std::vector<PackingGeometry> packings;
  for (const std::string& file : args.files) packings.push_back(readPacking(file, args.layers));
  // An offset wider than the container covers all of it, and a huge one overflows the clipper.
  if (args.visualize)
    for (const PackingGeometry& p : packings) {
      const Box box = bounds(p.container);
      const double side = std::max(box.width(), box.height());
      if (*args.visualize > side) throw InputError("--visualize", "must be 0 to the container's size, " + messageNumber(side));
    }

  const std::vector<Measured> measured = measurePackings(packings, args);
  EvennessOptions evenness;
  evenness.resolution = args.metrics.gridResolution;

  OutputBatch batch;  // every output, or none
  if (!args.csv.empty()) writeFileAtomically(args.csv, csvText(measured));
  if (!args.json.empty()) {
    json list = json::array();
    for (const Measured& m : measured) list.push_back(packingJson(m));
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
  std::cout << tableText(measured, args.calibrate) << evennessTableText(measured) << std::flush;
  return 0;
}

void declareMetricsOptions(CLI::App& command, MetricsArguments& args) {
  command.add_option("files", args.files, "Packing SVG files to measure and compare")->required()->type_name("PACKING");
  command.add_option("--report", args.report,
                     "Pak report (pak pack --report) to read d_gap from: \"d_gap\", or \"parameters\".\"gap\" / "
                     "\"canonical-scale\"")
      ->type_name("FILE");
  command.add_option("--config", args.config, "JSON file of option names to values (command-line flags win)")
      ->type_name("FILE");
  metricsOptions().addTo(command, args);
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

const CommandRegistrar registrar{subcommand<MetricsArguments>(
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
