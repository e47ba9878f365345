// Writes a Drawing as plain SVG 1.1: one <g> per DrawingGroup, one <path> per Shape, paint as
// presentation attributes (no CSS), so Inkscape, Illustrator, browsers and Pak's own reader
// all see the same picture. Top-level groups are also marked as Inkscape layers.
#include "pak/io/svg_writer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "io/svg_builder.hpp"
#include "pak/error.hpp"
#include "pak/io/atomic_file.hpp"

namespace pak {

std::string toSvgString(const Drawing& drawing, const SvgWriteOptions& options, SvgPathStats* stats) {
  int precision = std::clamp(options.precision, 0, 12);
  const double curveTolerance = std::isfinite(options.curveTolerance) ? std::max(0.0, options.curveTolerance) : 0.0;
  svg_builder::SvgBuilder builder(precision, curveTolerance);
  if (stats) *stats = {};
  builder.stats = stats;
  builder.beginDocument({&drawing});
  for (const DrawingGroup& group : drawing.groups) builder.writeGroup(group, 1);
  builder.endDocument();
  return std::move(builder.text());
}

void writeSvgFile(const Drawing& drawing, const std::string& path, const SvgWriteOptions& options,
                  SvgPathStats* stats) {
  std::string text;
  try {
    text = toSvgString(drawing, options, stats);
  } catch (const InputError& error) {
    throw InputError(path, error.what());
  }
  writeFileAtomically(path, text);
}

}  // namespace pak
