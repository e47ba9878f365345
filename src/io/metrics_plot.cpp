// Q, H and O of several packings side by side, drawn with cairo into PNG or SVG bytes.
#include "pak/io/metrics_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "io/cairo_output.hpp"
#include "pak/error.hpp"
#include "pak/io/atomic_file.hpp"

namespace pak {
namespace {

using namespace cairo_output;

constexpr std::array<std::array<double, 3>, 8> kColours = {{{0.12, 0.47, 0.71},
                                                            {0.84, 0.15, 0.16},
                                                            {0.17, 0.63, 0.17},
                                                            {1.00, 0.50, 0.05},
                                                            {0.58, 0.40, 0.74},
                                                            {0.55, 0.34, 0.29},
                                                            {0.89, 0.47, 0.76},
                                                            {0.50, 0.50, 0.50}}};
// Packing i: colour i mod 8, and past the first eight a line pattern (solid, dashed, dotted,
// dash-dot) by i / 8, so up to 32 packings stay distinguishable.
void setSeriesStyle(cairo_t* cr, std::size_t i) {
  const auto& colour = kColours[i % kColours.size()];
  cairo_set_source_rgb(cr, colour[0], colour[1], colour[2]);
  static const std::vector<double> patterns[] = {{}, {9.0, 4.0}, {2.0, 3.0}, {9.0, 3.0, 2.0, 3.0}};
  const std::vector<double>& dashes = patterns[(i / kColours.size()) % 4];
  cairo_set_dash(cr, dashes.data(), static_cast<int>(dashes.size()), 0);
}

constexpr double kLeft = 62, kRight = 16, kTop = 32, kBottom = 46, kLegendLine = 20;

// About five round ticks (1, 2 or 5 × 10^k) covering [0, top].
double tickStep(double top) {
  double raw = top / 5.0;
  double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

std::string label(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", std::fabs(value) < 1e-12 ? 0.0 : value);
  return buffer;
}

double curveMax(const std::vector<double>& values) {
  double top = 0.0;
  for (double v : values)
    if (std::isfinite(v)) top = std::max(top, v);
  return top;
}

struct Panel {
  const char* title;
  const Curve& (*curve)(const PackingMetrics&);
};

void drawPanel(cairo_t* cr, const std::vector<PackingMetrics>& packings, const Panel& panel, double x0, double width,
               double height) {
  double xTop = 0.0, yTop = 0.0;
  for (const PackingMetrics& m : packings) {
    xTop = std::max({xTop, curveMax(panel.curve(m).r), m.gap / 2.0});
    yTop = std::max(yTop, curveMax(panel.curve(m).value));
  }
  if (!(xTop > 0.0)) xTop = 1.0;
  if (!(yTop > 0.0)) yTop = 1.0;
  yTop *= 1.05;
  const double px = x0 + kLeft, py = kTop, pw = width - kLeft - kRight, ph = height - kTop - kBottom;
  auto X = [&](double r) { return px + pw * r / xTop; };
  auto Y = [&](double v) { return py + ph * (1.0 - v / yTop); };

  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_font_size(cr, 11);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, px, py, pw, ph);
  cairo_stroke(cr);
  cairo_text_extents_t extents;
  for (double step = tickStep(xTop), t = 0.0; t <= xTop * (1 + 1e-9); t += step) {
    cairo_move_to(cr, X(t), py + ph);
    cairo_line_to(cr, X(t), py + ph + 4);
    cairo_stroke(cr);
    std::string text = label(t);
    cairo_text_extents(cr, text.c_str(), &extents);
    cairo_move_to(cr, X(t) - extents.width / 2, py + ph + 16);
    cairo_show_text(cr, text.c_str());
  }
  for (double step = tickStep(yTop), t = 0.0; t <= yTop * (1 + 1e-9); t += step) {
    cairo_move_to(cr, px - 4, Y(t));
    cairo_line_to(cr, px, Y(t));
    cairo_stroke(cr);
    std::string text = label(t);
    cairo_text_extents(cr, text.c_str(), &extents);
    cairo_move_to(cr, px - 7 - extents.width, Y(t) + 4);
    cairo_show_text(cr, text.c_str());
  }
  cairo_set_font_size(cr, 13);
  cairo_text_extents(cr, panel.title, &extents);
  cairo_move_to(cr, px + pw / 2 - extents.width / 2, py - 10);
  cairo_show_text(cr, panel.title);
  cairo_move_to(cr, px + pw / 2 - 3, py + ph + 36);
  cairo_show_text(cr, "r");

  cairo_save(cr);
  cairo_rectangle(cr, px, py, pw, ph);
  cairo_clip(cr);
  for (std::size_t i = 0; i < packings.size(); ++i) {
    setSeriesStyle(cr, i);
    const Curve& curve = panel.curve(packings[i]);
    bool started = false;
    for (std::size_t k = 0; k < curve.r.size() && k < curve.value.size(); ++k) {
      if (!std::isfinite(curve.r[k]) || !std::isfinite(curve.value[k])) continue;
      if (started) cairo_line_to(cr, X(curve.r[k]), Y(curve.value[k]));
      else cairo_move_to(cr, X(curve.r[k]), Y(curve.value[k]));
      started = true;
    }
    cairo_set_line_width(cr, 1.8);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    // d_gap/2, the radius at which a perfect packing's Q reaches zero and O starts.
    const double dashes[] = {5.0, 4.0};
    cairo_set_dash(cr, dashes, 2, 0);
    cairo_set_line_width(cr, 1.0);
    cairo_move_to(cr, X(packings[i].gap / 2), py);
    cairo_line_to(cr, X(packings[i].gap / 2), py + ph);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  cairo_restore(cr);
}

void drawFigure(cairo_t* cr, const std::vector<PackingMetrics>& packings, const MetricsPlotOptions& options) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  const Panel panels[] = {
      {"Q(r): spherical contact probability", [](const PackingMetrics& m) -> const Curve& { return m.sphericalContact; }},
      {"H(r) = -Q'(r): distance histogram", [](const PackingMetrics& m) -> const Curve& { return m.distanceHistogram; }},
      {"O(r): overlap function", [](const PackingMetrics& m) -> const Curve& { return m.overlap; }}};
  for (int p = 0; p < 3; ++p)
    drawPanel(cr, packings, panels[p], p * options.panelWidth, options.panelWidth, options.panelHeight);
  cairo_set_font_size(cr, 12);
  for (std::size_t i = 0; i < packings.size(); ++i) {
    double y = options.panelHeight + kLegendLine * (i + 0.5);
    setSeriesStyle(cr, i);
    cairo_set_line_width(cr, 2.5);
    cairo_move_to(cr, kLeft, y);
    cairo_line_to(cr, kLeft + 28, y);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    cairo_set_source_rgb(cr, 0, 0, 0);
    std::string text = std::filesystem::path(packings[i].source).filename().string() + "  (dashed: d_gap/2 = " +
                       label(packings[i].gap / 2) + (packings[i].gapEstimated ? ", estimated)" : ")");
    cairo_move_to(cr, kLeft + 36, y + 4);
    cairo_show_text(cr, text.c_str());
  }
}

}  // namespace

void writeMetricsPlot(const std::vector<PackingMetrics>& packings, const std::string& path,
                      const MetricsPlotOptions& options) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".png" && extension != ".svg")
    throw InputError(path, "unknown plot format '" + extension + "' (use .png or .svg)");
  checkOutputPath(path);  // a missing folder fails before drawing
  const int width = 3 * options.panelWidth;
  const int height = options.panelHeight + static_cast<int>(kLegendLine * (packings.size() + 0.5));
  std::string bytes;
  SurfacePtr surface(extension == ".svg"
                         ? cairo_svg_surface_create_for_stream(appendToString, &bytes, width, height)
                         : cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  {
    ContextPtr cr(cairo_create(surface.get()));
    drawFigure(cr.get(), packings, options);
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS) throw InputError(path, "cannot draw the plot");
  }
  if (extension == ".png") {
    if (cairo_surface_write_to_png_stream(surface.get(), appendToString, &bytes) != CAIRO_STATUS_SUCCESS)
      throw InputError(path, "cannot encode the plot as PNG");
  } else {
    cairo_surface_finish(surface.get());  // flushes the SVG into `bytes`
  }
  const bool drawn = cairo_surface_status(surface.get()) == CAIRO_STATUS_SUCCESS;
  surface.reset();
  releaseFontCaches();
  if (!drawn) throw InputError(path, "cannot draw the plot");
  writeFileAtomically(path, bytes);
}

}  // namespace pak
