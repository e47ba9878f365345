// A contact sheet: chosen frames of an animation side by side in rows, each with a thin
// border and a caption underneath, like the frame strips of the thesis's figures.
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "io/animation_frames.hpp"
#include "io/cairo_output.hpp"
#include "io/drawing_raster.hpp"
#include "pak/error.hpp"
#include "pak/io/animation_output.hpp"
#include "pak/io/atomic_file.hpp"

namespace pak {

void writeContactSheet(const std::vector<Drawing>& frames, const std::vector<std::string>& captions,
                       const std::string& path, int columns, const AnimationOutputOptions& options) {
  using cairo_output::ContextPtr;
  using cairo_output::SurfacePtr;
  animation_frames::checkFrames(frames, options, path);
  if (columns < 1) throw InputError(path, "contact sheet needs at least 1 column, not " + std::to_string(columns));
  if (!captions.empty() && captions.size() != frames.size())
    throw InputError(path, std::to_string(captions.size()) + " captions for " + std::to_string(frames.size()) +
                               " frames (give one per frame, or none)");
  checkOutputPath(path);  // a missing folder fails before the rendering

  // Every cell is one frame at options.width, with a caption strip under it when captioned.
  const PngOptions png = animation_frames::rasterOptions(frames, options, path);
  const int cellWidth = png.width, frameHeight = png.height;
  const double fontSize = std::clamp(cellWidth / 16.0, 10.0, 48.0);
  const int captionHeight = captions.empty() ? 0 : static_cast<int>(std::ceil(fontSize * 1.8));
  const int cellHeight = frameHeight + captionHeight;
  const int used = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(columns), frames.size()));
  const long long rows = (static_cast<long long>(frames.size()) + used - 1) / used;
  const long long sheetWidth = static_cast<long long>(used) * cellWidth, sheetHeight = rows * cellHeight;
  if (sheetWidth > raster::kMaxPixels || sheetHeight > raster::kMaxPixels)
    throw InputError(path, "contact sheet would be " + std::to_string(sheetWidth) + " x " + std::to_string(sheetHeight) +
                               " pixels; at most " + std::to_string(raster::kMaxPixels) +
                               " a side (fewer frames, other columns or a lower width)");

  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(sheetWidth),
                                                static_cast<int>(sheetHeight)));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw InputError(path, std::string("cannot create the contact sheet: ") +
                               cairo_status_to_string(cairo_surface_status(surface.get())));
  bool drawn = false;
  {
    ContextPtr context(cairo_create(surface.get()));
    cairo_t* cr = context.get();
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_GOOD);
    if (options.background) {
      const Color& c = *options.background;
      cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, std::clamp(c.alpha, 0.0, 1.0));
      cairo_paint(cr);
    }
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, fontSize);
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const double x = static_cast<double>(i % used) * cellWidth, y = static_cast<double>(i / used) * cellHeight;
      cairo_save(cr);
      cairo_rectangle(cr, x, y, cellWidth, frameHeight);
      cairo_clip(cr);
      cairo_translate(cr, x, y);
      raster::paintDrawing(cr, frames[i], cellWidth, frameHeight);
      cairo_restore(cr);
      // A one-pixel grey border inside the cell, on pixel centres so it stays crisp.
      cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
      cairo_set_line_width(cr, 1.0);
      cairo_rectangle(cr, x + 0.5, y + 0.5, cellWidth - 1.0, frameHeight - 1.0);
      cairo_stroke(cr);
      if (!captions.empty() && !captions[i].empty()) {
        cairo_text_extents_t extents;
        cairo_text_extents(cr, captions[i].c_str(), &extents);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_move_to(cr, x + (cellWidth - extents.width) / 2.0 - extents.x_bearing,
                      y + frameHeight + captionHeight / 2.0 - extents.height / 2.0 - extents.y_bearing);
        cairo_show_text(cr, captions[i].c_str());
      }
    }
    drawn = cairo_status(cr) == CAIRO_STATUS_SUCCESS;
  }
  std::string bytes;
  if (drawn) drawn = cairo_surface_write_to_png_stream(surface.get(), cairo_output::appendToString, &bytes) ==
                     CAIRO_STATUS_SUCCESS;
  surface.reset();
  if (!captions.empty()) cairo_output::releaseFontCaches();
  if (!drawn) throw InputError(path, "cannot draw the contact sheet");
  writeFileAtomically(path, bytes);
}

}  // namespace pak
