#pragma once
// Figures of the packing metrics, drawn with cairo: PNG or SVG by the file's extension.
#include <string>
#include <vector>

#include "pak/metrics/metrics.hpp"

namespace pak {

struct MetricsPlotOptions {
  int panelWidth = 480;  // pixels (PNG) or points (SVG) per panel
  int panelHeight = 360;
};

// Q(r), H(r) and O(r) side by side, one colour per packing, a legend with the file names and
// each packing's d_gap/2 marked by a dashed line. Written atomically; throws InputError when
// the file cannot be written or its extension is neither .png nor .svg.
void writeMetricsPlot(const std::vector<PackingMetrics>& packings, const std::string& path,
                      const MetricsPlotOptions& = {});

}  // namespace pak
