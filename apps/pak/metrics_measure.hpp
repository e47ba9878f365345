#pragma once
// What `pak metrics` measures on packings and writes as JSON, shared by the command line and
// pak.metrics: one packing's chapter-6 metrics and its evenness, on the same geometry.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "metrics_arguments.hpp"
#include "pak/metrics/evenness.hpp"

namespace pak::cli {

struct MeasuredPacking {
  PackingMetrics metrics;
  Evenness evenness;
  std::optional<double> calibrationOffset;  // with --calibrate
};

// d_gap in the packing's units from a Pak report: an explicit "d_gap", else the canonical
// gap of `pak pack` divided by the canonical units per input unit. Errors name `where`.
double gapFromReport(const nlohmann::json& report, const std::string& where);
// A report file as JSON (a syntax error names the file and line).
nlohmann::json readReportFile(const std::string& path);

// Measures each packing with `args`'s options (calibrated first with --calibrate);
// `packings` is changed by the calibration.
std::vector<MeasuredPacking> measurePackings(std::vector<PackingGeometry>& packings, const MetricsArguments& args);

// One packing's entry of `--json`'s "packings".
nlohmann::json packingJson(const MeasuredPacking& measured);

}  // namespace pak::cli
