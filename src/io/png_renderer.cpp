// Renders a Drawing with cairo into an anti-aliased ARGB image and saves it as PNG, or hands
// the pixels to the animation writers (drawing_raster.hpp).
// Every call owns its surface and context, so concurrent calls (tests, batch renders) are safe.
#include "pak/io/png_renderer.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

#include "io/cairo_output.hpp"
#include "io/drawing_raster.hpp"
#include "pak/error.hpp"
#include "pak/io/atomic_file.hpp"

namespace pak {
namespace {

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
    // A dot: cairo caps a zero-length segment, not a lone move.
    if (subpath.points.size() == 1 && !subpath.closed) cairo_line_to(context, subpath.points[0].x, subpath.points[0].y);
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
    cairo_set_line_cap(context, shape.lineCap == StrokeCap::Butt    ? CAIRO_LINE_CAP_BUTT
                                : shape.lineCap == StrokeCap::Square ? CAIRO_LINE_CAP_SQUARE
                                                                     : CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(context, shape.lineJoin == StrokeJoin::Miter   ? CAIRO_LINE_JOIN_MITER
                                 : shape.lineJoin == StrokeJoin::Bevel ? CAIRO_LINE_JOIN_BEVEL
                                                                       : CAIRO_LINE_JOIN_ROUND);
    cairo_set_miter_limit(context, shape.miterLimit);
    cairo_set_dash(context, shape.dashArray.data(), static_cast<int>(shape.dashArray.size()), shape.dashOffset);
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

namespace raster {

PixelSize pixelSize(const Drawing& drawing, const PngOptions& options, const std::string& where) {
  if (options.width < 1 || options.width > kMaxPixels)
    throw InputError(where, "PNG width " + std::to_string(options.width) + " is out of range (1 to " +
                                std::to_string(kMaxPixels) + " pixels)");
  if (options.height > kMaxPixels)
    throw InputError(where, "PNG height " + std::to_string(options.height) + " is out of range (1 to " +
                                std::to_string(kMaxPixels) + " pixels)");
  if (options.height > 0) return {options.width, options.height};
  Box box = drawingBox(drawing);
  double exactHeight = std::round(box.height() * (options.width / box.width()));
  if (!(exactHeight <= kMaxPixels))
    throw InputError(where, "PNG would be " + std::to_string(options.width) + " x " +
                                std::to_string(static_cast<long long>(std::min(exactHeight, 1e15))) +
                                " pixels; at most " + std::to_string(kMaxPixels) + " a side (lower --width)");
  return {options.width, std::max(1, static_cast<int>(exactHeight))};
}

void paintDrawing(cairo_t* context, const Drawing& drawing, double width, double height) {
  cairo_save(context);
  // Map the box onto the rectangle like SVG's default preserveAspectRatio (xMidYMid meet): one
  // scale for both axes, centred; a rounded height leaves sub-pixel slack, centred too.
  Box box = drawingBox(drawing);
  double uniform = std::min(width / box.width(), height / box.height());
  cairo_translate(context, (width - box.width() * uniform) / 2.0, (height - box.height() * uniform) / 2.0);
  cairo_scale(context, uniform, uniform);
  cairo_translate(context, -box.min.x, -box.min.y);
  // SVG's defaults (cairo's miter limit is 10, SVG's 4).
  cairo_set_line_join(context, CAIRO_LINE_JOIN_MITER);
  cairo_set_line_cap(context, CAIRO_LINE_CAP_BUTT);
  cairo_set_miter_limit(context, 4.0);
  for (const DrawingGroup& group : drawing.groups) drawGroup(context, group);
  cairo_restore(context);
}

SurfacePtr renderSurface(const Drawing& drawing, const PngOptions& options, const std::string& where) {
  PixelSize size = pixelSize(drawing, options, where);
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, size.width, size.height));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw InputError(where, std::string("cannot create a ") + std::to_string(size.width) + " x " +
                                std::to_string(size.height) + " image: " +
                                cairo_status_to_string(cairo_surface_status(surface.get())));
  ContextPtr context(cairo_create(surface.get()));
  cairo_set_antialias(context.get(), CAIRO_ANTIALIAS_GOOD);
  // A new image surface is fully transparent; paint the background if there is one.
  if (options.background) {
    setColor(context.get(), *options.background, 1.0);
    cairo_paint(context.get());
  }
  paintDrawing(context.get(), drawing, size.width, size.height);
  if (cairo_status(context.get()) != CAIRO_STATUS_SUCCESS)
    throw InputError(where, std::string("cannot render: ") + cairo_status_to_string(cairo_status(context.get())));
  cairo_surface_flush(surface.get());
  return surface;
}

RgbaImage toRgba(cairo_surface_t* surface) {
  cairo_surface_flush(surface);
  RgbaImage image;
  image.width = cairo_image_surface_get_width(surface);
  image.height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  image.rgba.resize(static_cast<std::size_t>(image.width) * image.height * 4);
  std::uint8_t* out = image.rgba.data();
  for (int y = 0; y < image.height; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::size_t>(y) * stride);
    for (int x = 0; x < image.width; ++x, out += 4) {
      std::uint32_t word = row[x];  // ARGB32: alpha in the top byte, in native byte order
      std::uint32_t a = word >> 24;
      auto channel = [&](int shift) -> std::uint8_t {
        std::uint32_t premultiplied = (word >> shift) & 0xffu;
        return a == 0 ? 0 : static_cast<std::uint8_t>(std::min<std::uint32_t>(255, (premultiplied * 255 + a / 2) / a));
      };
      out[0] = channel(16);
      out[1] = channel(8);
      out[2] = channel(0);
      out[3] = static_cast<std::uint8_t>(a);
    }
  }
  return image;
}

}  // namespace raster

void writePngFile(const Drawing& drawing, const std::string& path, const PngOptions& options) {
  // Check the destination first: a missing folder should fail before seconds of rendering.
  checkOutputPath(path);  // throws InputError when the folder is missing or read-only
  // Encode in memory, then reuse the atomic writer: one code path for every output file.
  writeFileAtomically(path, renderPng(drawing, options, path));
}

std::string renderPng(const Drawing& drawing, const PngOptions& options, const std::string& where) {
  SurfacePtr surface = raster::renderSurface(drawing, options, where);
  std::string png;
  cairo_status_t status = cairo_surface_write_to_png_stream(surface.get(), appendToString, &png);
  if (status != CAIRO_STATUS_SUCCESS)
    throw InputError(where, std::string("cannot encode PNG: ") + cairo_status_to_string(status));
  return png;
}

RgbaImage renderToImage(const Drawing& drawing, const PngOptions& options) {
  SurfacePtr surface = raster::renderSurface(drawing, options, "");
  return raster::toRgba(surface.get());
}

}  // namespace pak
