// Thesis Fig. 6.4: how the offset elements meet. Overlaps (red) appear where the negative
// space is narrower than 2r; grey container left uncovered is wider than 2r.
#include "pak/io/offset_visualization.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/cairo_output.hpp"
#include "pak/error.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/io/atomic_file.hpp"

namespace pak {
namespace {

using namespace cairo_output;

void addRegionPath(cairo_t* cr, const Region& region) {
  auto ring = [&](const Ring& points) {
    if (points.size() < 3) return;
    cairo_move_to(cr, points[0].x, points[0].y);
    for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr, points[i].x, points[i].y);
    cairo_close_path(cr);
  };
  for (const Polygon& polygon : region) {
    ring(polygon.outer);
    for (const Ring& hole : polygon.holes) ring(hole);
  }
}

void fillRegion(cairo_t* cr, const Region& region, double r, double g, double b, double a) {
  cairo_new_path(cr);
  addRegionPath(cr, region);
  cairo_set_source_rgba(cr, r, g, b, a);
  cairo_fill(cr);
}

}  // namespace

void writeOffsetVisualization(const PackingGeometry& packing, double r, const std::string& path, int width) {
  checkOutputPath(path);  // a missing folder fails before the offsets are computed
  if (width < 16 || width > 16384) throw InputError(path, "visualization width must be 16 to 16384 pixels");
  if (!std::isfinite(r) || r < 0.0) throw InputError(path, "the visualization offset must be non-negative");
  Box box = bounds(packing.container);
  if (box.empty() || !(box.width() > 0.0) || !(box.height() > 0.0))
    throw InputError(packing.source, "no container to draw");
  const double extent = std::max(box.width(), box.height());
  const double margin = 0.02 * extent + r;
  const double scale = width / (box.width() + 2 * margin);
  const int height = std::clamp(static_cast<int>(std::lround((box.height() + 2 * margin) * scale)), 1, 16384);

  OffsetOptions offsetOptions;
  offsetOptions.arcTolerance = 1e-4 * extent;
  offsetOptions.precision = std::min(offsetOptions.precision, 1e-7 * extent);
  ClipOptions clip{offsetOptions.precision};
  std::vector<Region> grown;
  std::vector<Box> boxes;
  for (const Region& element : packing.elements) {
    grown.push_back(r > 0.0 ? offset(element, r, offsetOptions) : element);
    boxes.push_back(bounds(grown.back()));
  }
  // Pairwise intersections, only between elements whose boxes meet: covered twice or more.
  std::vector<Region> overlaps;
  for (std::size_t i = 0; i < grown.size(); ++i)
    for (std::size_t j = i + 1; j < grown.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) {
        Region both = intersect(grown[i], grown[j], clip);
        if (!both.empty()) overlaps.push_back(std::move(both));
      }

  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  ContextPtr owner(cairo_create(surface.get()));
  cairo_t* cr = owner.get();
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_scale(cr, scale, scale);
  cairo_translate(cr, margin - box.min.x, margin - box.min.y);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);  // holes are the rings inside
  fillRegion(cr, packing.container, 0.82, 0.82, 0.82, 1.0);
  for (const Region& region : grown) fillRegion(cr, region, 0.35, 0.45, 0.60, 0.55);
  for (const Region& element : packing.elements) fillRegion(cr, element, 0.15, 0.15, 0.2, 1.0);
  for (const Region& overlap : overlaps) fillRegion(cr, overlap, 0.9, 0.05, 0.05, 1.0);
  cairo_new_path(cr);
  addRegionPath(cr, packing.container);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0 / scale);
  cairo_stroke(cr);
  owner.reset();

  std::string bytes;
  if (cairo_surface_write_to_png_stream(surface.get(), appendToString, &bytes) != CAIRO_STATUS_SUCCESS)
    throw InputError(path, "cannot encode the visualization as PNG");
  writeFileAtomically(path, bytes);
}

}  // namespace pak
