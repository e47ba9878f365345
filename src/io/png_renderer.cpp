// Renders a Drawing with cairo into an anti-aliased ARGB image and saves it as PNG.
// Every call owns its surface and context, so concurrent calls (tests, batch renders) are safe.
#include "pak/png_renderer.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "cairo_output.hpp"
#include "pak/atomic_file.hpp"
#include "pak/error.hpp"

namespace pak {
namespace {

// Big enough for print previews, small enough that a typo in --width cannot eat the memory
// (16384² × 4 bytes = 1 GiB), and inside cairo's 32767-pixel limit.
constexpr int kMaxPixels = 16384;

using cairo_output::appendToString;
using cairo_output::ContextPtr;
using cairo_output::SurfacePtr;

// The drawing's box, or the bounds of what it draws when the box was left empty.
Box drawingBox(const Drawing& drawing) {
  if (!drawing.viewBox.empty() && drawing.viewBox.width() > 0.0 && drawing.viewBox.height() > 0.0)
    return drawing.viewBox;
  Box box;
  auto addGroup = [&](const DrawingGroup& group, auto& self) -> void {
    for (const Shape& shape : group.shapes)
      for (const Subpath& subpath : shape.subpaths)
        for (Vec2 p : subpath.points)
          if (std::isfinite(p.x) && std::isfinite(p.y)) box.add(p);
    for (const DrawingGroup& child : group.children) self(child, self);
  };
  for (const DrawingGroup& group : drawing.groups) addGroup(group, addGroup);
  if (box.empty() || box.width() <= 0.0 || box.height() <= 0.0) {
    // Nothing (or a line) to frame: a unit square around it keeps the aspect ratio sane.
    Vec2 center = box.empty() ? Vec2{0.5, 0.5} : box.center();
    double side = box.empty() ? 1.0 : std::max({box.width(), box.height(), 1.0});
    return Box{center - Vec2{side, side} * 0.5, center + Vec2{side, side} * 0.5};
  }
  return box;
}

void setColor(cairo_t* context, const Color& color, double opacity) {
  cairo_set_source_rgba(context, color.r / 255.0, color.g / 255.0, color.b / 255.0,
                        std::clamp(color.alpha * opacity, 0.0, 1.0));
}

void tracePath(cairo_t* context, const Shape& shape) {
  cairo_new_path(context);
  for (const Subpath& subpath : shape.subpaths) {
    if (subpath.points.empty()) continue;
    cairo_move_to(context, subpath.points[0].x, subpath.points[0].y);
    for (std::size_t i = 1; i < subpath.points.size(); ++i)
      cairo_line_to(context, subpath.points[i].x, subpath.points[i].y);
    if (subpath.closed) cairo_close_path(context);
  }
}

void drawShape(cairo_t* context, const Shape& shape) {
  if (shape.opacity <= 0.0) return;
  bool fills = shape.fill.has_value();
  bool strokes = shape.stroke.has_value() && shape.strokeWidth > 0.0;
  if (!fills && !strokes) return;
  // SVG's `opacity` applies to the fill and stroke together (the stroke must not show the
  // fill through it), so when both are painted render them as one group and fade the group.
  bool asGroup = fills && strokes && shape.opacity < 1.0;
  double paintOpacity = asGroup ? 1.0 : shape.opacity;
  if (asGroup) cairo_push_group(context);
  tracePath(context, shape);
  if (fills) {
    cairo_set_fill_rule(context, shape.fillRule == FillRule::EvenOdd ? CAIRO_FILL_RULE_EVEN_ODD
                                                                     : CAIRO_FILL_RULE_WINDING);
    setColor(context, *shape.fill, paintOpacity);
    if (strokes)
      cairo_fill_preserve(context);
    else
      cairo_fill(context);
  }
  if (strokes) {
    cairo_set_line_width(context, shape.strokeWidth);
    setColor(context, *shape.stroke, paintOpacity);
    cairo_stroke(context);
  }
  if (asGroup) {
    cairo_pop_group_to_source(context);
    cairo_paint_with_alpha(context, shape.opacity);
  }
}

void drawGroup(cairo_t* context, const DrawingGroup& group) {
  if (group.clip) {
    cairo_save(context);
    cairo_rectangle(context, group.clip->min.x, group.clip->min.y, group.clip->width(), group.clip->height());
    cairo_clip(context);
  }
  for (const Shape& shape : group.shapes) drawShape(context, shape);
  for (const DrawingGroup& child : group.children) drawGroup(context, child);
  if (group.clip) cairo_restore(context);
}


}  // namespace

void writePngFile(const Drawing& drawing, const std::string& path, const PngOptions& options) {
  // Check the destination first: a missing folder should fail before seconds of rendering.
  (void)temporaryPathFor(path);  // throws InputError when the folder is missing or read-only

  if (options.width < 1 || options.width > kMaxPixels)
    throw InputError(path, "PNG width " + std::to_string(options.width) + " is out of range (1 to " +
                               std::to_string(kMaxPixels) + " pixels)");
  Box box = drawingBox(drawing);
  double scale = options.width / box.width();
  double exactHeight = std::round(box.height() * scale);
  if (!(exactHeight <= kMaxPixels))
    throw InputError(path, "PNG would be " + std::to_string(options.width) + " x " +
                               std::to_string(static_cast<long long>(std::min(exactHeight, 1e15))) +
                               " pixels; at most " + std::to_string(kMaxPixels) + " a side (lower --width)");
  int width = options.width;
  int height = std::max(1, static_cast<int>(exactHeight));

  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw InputError(path, std::string("cannot create a ") + std::to_string(width) + " x " +
                               std::to_string(height) + " image: " +
                               cairo_status_to_string(cairo_surface_status(surface.get())));
  ContextPtr context(cairo_create(surface.get()));
  cairo_set_antialias(context.get(), CAIRO_ANTIALIAS_GOOD);

  // A new image surface is fully transparent; paint the background if there is one.
  if (options.background) {
    setColor(context.get(), *options.background, 1.0);
    cairo_paint(context.get());
  }

  // Map the box onto the image like SVG's default preserveAspectRatio (xMidYMid meet): one
  // scale for both axes, centred; the height was rounded, so centre the sub-pixel slack.
  double uniform = std::min(width / box.width(), height / box.height());
  cairo_translate(context.get(), (width - box.width() * uniform) / 2.0, (height - box.height() * uniform) / 2.0);
  cairo_scale(context.get(), uniform, uniform);
  cairo_translate(context.get(), -box.min.x, -box.min.y);
  // SVG's defaults (cairo's miter limit is 10, SVG's 4).
  cairo_set_line_join(context.get(), CAIRO_LINE_JOIN_MITER);
  cairo_set_line_cap(context.get(), CAIRO_LINE_CAP_BUTT);
  cairo_set_miter_limit(context.get(), 4.0);

  for (const DrawingGroup& group : drawing.groups) drawGroup(context.get(), group);

  if (cairo_status(context.get()) != CAIRO_STATUS_SUCCESS)
    throw InputError(path, std::string("cannot render: ") + cairo_status_to_string(cairo_status(context.get())));
  cairo_surface_flush(surface.get());

  // Encode in memory, then reuse the atomic writer: one code path for every output file.
  std::string png;
  cairo_status_t status = cairo_surface_write_to_png_stream(surface.get(), appendToString, &png);
  if (status != CAIRO_STATUS_SUCCESS)
    throw InputError(path, std::string("cannot encode PNG: ") + cairo_status_to_string(status));
  writeFileAtomically(path, png);
}

}  // namespace pak
