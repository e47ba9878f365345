#pragma once
// What the output of a run shows of its scene, besides the packed elements: the document's
// coordinate box and size, the container shapes as the artist drew them, the fixed layer and
// the scene's other layers as written. The scene loader reads it with the scene;
// packingDrawing and flowDrawing draw every packing of that scene on it.
#include <string>
#include <vector>

#include "pak/geom/box.hpp"
#include "pak/io/raw_markup.hpp"
#include "pak/io/svg_shape.hpp"

namespace pak {

struct ContainerShape {
  SvgShape shape;
  // Drawn with its own paint: it comes from a `container` layer (or is an element of the
  // packing whose elements are now the containers). false: the file is a container by itself
  // (an icon, a .path outline), drawn as an outline or its fill would hide the elements.
  bool keepsPaint = false;
};

// A layer of the scene no method uses (a background, a title, a frame): outputs show it as the
// artist drew it.
struct SceneLayer {
  std::string name;              // its inkscape:label, else its id, as written
  std::vector<SvgShape> shapes;  // what Pak reads of it: the PNG previews draw these
  RawMarkup markup;              // the layer as written, its own <g> included, which the SVG
                                 // output copies; empty: the output re-draws `shapes`
};

struct SceneLayout {
  Box viewBox;                       // the document's coordinate box
  double width = 0.0, height = 0.0;  // the document's size in its own user units
  std::string widthText, heightText; // and as written ("210mm"); "" when it has none (SvgDocument)
  std::vector<ContainerShape> containerShapes;
  std::vector<SvgShape> fixedShapes; // the fixed elements (Scene::fixed) as read
  RawMarkup fixedMarkup;             // the `fixed` layer as written (SVG input): the output copies
                                     // it unchanged; empty: the output re-draws fixedShapes
  // The other layers, in document order: those before the container layer in the file are
  // drawn under it, the others over the packed elements.
  std::vector<SceneLayer> layersBelow, layersAbove;
};

}  // namespace pak
