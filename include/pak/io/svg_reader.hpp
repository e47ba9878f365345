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

// A group at the top of the document (a layer, in an editor), for outputs that copy the
// layers a scene does not use.
struct SvgTopGroup {
  std::string name;                 // its inkscape:label, else its id, as written ("" for neither)
  std::vector<std::string> layers;  // the layer names its shapes get (SvgShape::layer), its own first
  // The group as written, its own tag included, with the definitions it references; empty when
  // a <style> sheet styles it (the copy would lose those colours) or it is not in the source
  // text (a top-level <use>, expanded).
  RawMarkup markup;
  bool styledBySheet = false;       // why the markup is empty, when it is
};

struct SvgDocument {
  std::string file;
  Box viewBox;                       // in user units (viewBox attribute, else 0 0 width height)
  double width = 0.0, height = 0.0;  // in user units after resolving units like mm
  // The root's width and height as written ("210mm", "8.5in", "100%"), so that outputs keep
  // the document's size in its own units; "" when absent, or when the drawing's bounds make
  // the box (no viewBox, not both sizes).
  std::string widthText, heightText;
  std::vector<std::string> layers;   // names of the layers found, lower-cased, in order
  std::vector<SvgShape> shapes;      // in document order, in viewBox coordinates
  // For each top-level <g> (indexed by SvgShape::topGroup): is it an Inkscape layer
  // (inkscape:groupmode="layer")?
  std::vector<bool> inkscapeLayers;
  std::vector<Warning> warnings;     // things skipped and why
  // The visible `fixed` layers' children as written, in a <g> placing them, for outputs to copy
  // unchanged; empty when there is none or when a stylesheet styles them (outputs then re-draw
  // `shapes`).
  RawMarkup fixedMarkup;
  std::vector<SvgTopGroup> topGroups;  // in document order: SvgShape::topGroup indexes it
};

// Throws InputError for an unreadable file, non-XML, XML that is not SVG, or bad numbers.
SvgDocument readSvgFile(const std::string& path, const SvgReadOptions& = {});
SvgDocument readSvgString(const std::string& text, const std::string& name, const SvgReadOptions& = {});

}  // namespace pak
