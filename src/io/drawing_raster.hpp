#pragma once
// The cairo drawing code behind every raster output (PNG, PNG frames, GIF, video, contact
// sheets), so all of them show a Drawing exactly alike. Implemented in png_renderer.cpp.
#include <cairo.h>

#include <string>

#include "io/cairo_output.hpp"
#include "pak/io/drawing.hpp"
#include "pak/io/png_renderer.hpp"

namespace pak::raster {

constexpr int kMaxPixels = kMaxPngPixels;

struct PixelSize {
  int width = 0, height = 0;
};

// The image size writePngFile would use; throws InputError (naming `where`) when it is out of
// range.
PixelSize pixelSize(const Drawing& drawing, const PngOptions& options, const std::string& where);

// Draws the drawing fitted into the rectangle (0, 0)-(width, height) of the current user space,
// centred like SVG's xMidYMid meet. Paints no background; leaves the context's state as it was.
void paintDrawing(cairo_t* context, const Drawing& drawing, double width, double height);

// A new image surface of pixelSize() with the background and the drawing.
cairo_output::SurfacePtr renderSurface(const Drawing& drawing, const PngOptions& options, const std::string& where);

// The surface's pixels as straight RGBA (cairo keeps them premultiplied, in native byte order).
RgbaImage toRgba(cairo_surface_t* surface);

}  // namespace pak::raster
