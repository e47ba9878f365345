#pragma once
// A shape as its document gives it: the core Shape (geometry and paint) and what only reading
// and writing documents uses: its SVG id and element, where it is in the file, its layer and
// groups, and the attributes a scene's containers carry. Passing it where a Shape is
// taken hands the core just the geometry and paint.
#include <string>
#include <vector>

#include "pak/geom/art.hpp"
#include "pak/geom/box.hpp"

namespace pak {

struct SvgShape : Shape {
  std::string id;                // the SVG id, if any
  std::string tag;               // "path", "rect", … or "path-file" for .path input
  int line = 0;                  // line of its element (.path: of its path) in the file; 0: unknown
  std::string layer;             // lower-cased name of the enclosing layer ("" if none)
  int topGroup = -1;             // index of the enclosing top-level <g>, -1 if none
  int layerGroup = -1;           // index of the enclosing direct child <g> of the layer's group
                                 // (one packed element in Pak's output), -1 if none
  std::string elements;          // `data-elements` of the shape or its nearest group that has
                                 // one: the library a container shape asks for ("" if none)
  std::string gap;               // `data-gap`, likewise: a container's own FLOWPAK s_gap ("" if none)
};

// As bounds(const std::vector<Shape>&): the points, grown by half the stroke where stroked.
Box bounds(const std::vector<SvgShape>& shapes);

}  // namespace pak
