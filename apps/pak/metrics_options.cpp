// `pak metrics`'s options, each declared once: flag and --config key (and pak.metrics's
// keyword arguments).
#include "metrics_arguments.hpp"

namespace pak::cli {

const OptionTable<MetricsArguments>& metricsOptions() {
  using A = MetricsArguments;
  using M = MetricsOptions;
  using L = PackingReadOptions;
  static const OptionTable<A> table{
      {"gap", field(&A::metrics, &M::gap), "d_gap in the file's units (0: from --report, else estimated)"},
      {"radii", field(&A::metrics, &M::radii), "samples of r for Q, H and O"},
      {"grid", field(&A::metrics, &M::gridResolution), "distance-transform grid cells along the container's bounding square, for the histogram, the distance map and the evenness measure"},
      {"bins", field(&A::metrics, &M::histogramBins), "bins of the discrete distance histogram"},
      {"arc-tolerance", field(&A::metrics, &M::arcTolerance), "largest error of the polygon offsets and of the outline simplification before them, in the file's units (0: 1e-4 of the container's bounding square)"},
      {"calibrate", field(&A::calibrate), "offset every packing's elements uniformly to the packings' mean negative-space ratio first (thesis 6.4), and report the offset"},
      {"container-layer", field(&A::layers, &L::containerLayer), "layer holding the container"},
      {"elements-layer", field(&A::layers, &L::elementsLayer), "layer whose child groups are the elements"},
      {"fixed-layer", field(&A::layers, &L::fixedLayer), "layer of fixed elements, positive space for the evenness measure"},
  };
  return table;
}

}  // namespace pak::cli
