#pragma once
// Reads SVG documents (SVG++ underneath) into flattened shapes with paint and layers.
#include <string>
#include <vector>

#include "pak/geom/box.hpp"
#include "pak/io/raw_markup.hpp"
#include "pak/io/svg_shape.hpp"
#include "pak/io/warning.hpp"

namespace pak {

struct SvgReadOptions {
  // Curve flattening tolerance, as a fraction of the document's larger viewBox side
  // (1e-4 = 0.1 unit in Pak's 1000-wide canonical frame).
  double flatness = 1e-4;
};

struct SvgDocument {
  std::string file;
  Box viewBox;                       // in user units (viewBox attribute, else 0 0 width height)
  double width = 0.0, height = 0.0;  // in user units after resolving units like mm
  std::vector<std::string> layers;   // names of the layers found, lower-cased, in order
  std::vector<SvgShape> shapes;      // in document order, in viewBox coordinates
  // For each top-level <g> (indexed by SvgShape::topGroup): is it an Inkscape layer
  // (inkscape:groupmode="layer")?
  std::vector<bool> inkscapeLayers;
  std::vector<Warning> warnings;     // things skipped and why
  // The visible `fixed` layers' children as written, for outputs to copy unchanged; empty when
  // there is none or when a stylesheet styles them (outputs then re-draw `shapes`).
  RawMarkup fixedMarkup;
};

// Throws InputError for an unreadable file, non-XML, XML that is not SVG, or bad numbers.
SvgDocument readSvgFile(const std::string& path, const SvgReadOptions& = {});
SvgDocument readSvgString(const std::string& text, const std::string& name, const SvgReadOptions& = {});

}  // namespace pak
