#pragma once
// What the packers consume: a scene (containers, fixed elements, guides, spines) and a
// library of elements. Built by src/io from files; the core never reads files itself.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "pak/geom/art.hpp"
#include "pak/geom/polygon.hpp"
#include "pak/io/raw_markup.hpp"

namespace pak {

struct Warning {
  std::string where;    // file and element id or line
  std::string message;  // what was skipped and why
};

struct ContainerPart;

struct Scene {
  std::string source;
  Box viewBox;                      // the document's coordinate box
  double width = 0.0, height = 0.0; // the document's size in its own user units
  std::vector<Shape> containerShapes;
  Region container;                 // union of the container shapes, holes subtracted
  // The separate containers (disjoint parts of `container`, each with its holes, or one per
  // element of a previous packing): every element stays in the one it was seeded in.
  // Empty: each polygon of `container` is one container, filled from the run's library.
  std::vector<ContainerPart> containers;
  std::vector<Shape> fixed;         // fixed elements: obstacles, and drawn in the output
  RawMarkup fixedMarkup;            // the `fixed` layer as written (SVG input): the output copies
                                    // it unchanged; empty: the output re-draws `fixed`
  std::vector<Polyline> guides;     // FLOWPAK direction strokes
  std::vector<Polyline> spines;     // FLOWPAK fixed spines
  std::vector<Warning> warnings;
};

// A named point of an element (a `<circle id="handle-NAME">` in its SVG, not part of the
// art), in the element file's coordinates: what AnimationPak's shape animation moves.
struct ElementHandle {
  std::string name;
  Vec2 position;
};

struct ElementArt {
  std::string source;   // file the element came from
  std::string name;     // file stem, or group id for a multi-element SVG
  std::vector<Shape> shapes;
  Region outline;       // union of everything the art paints (holes kept)
  std::optional<std::array<Vec2, 2>> spine;  // FLOWPAK spine if the file gives one
  std::vector<ElementHandle> handles;        // AnimationPak handles, if the file gives any
  std::vector<Warning> warnings;  // the reader's and the element's: what was ignored and why
};

using Library = std::vector<ElementArt>;

struct ContainerPart {
  Region region;
  // Its own library (the `data-elements` attribute of its shape or of an enclosing group):
  // the files as resolved against the scene file, and the elements loadScene read from them.
  // Empty: filled from the run's library.
  std::vector<std::string> elementFiles;
  Library library;
  // Its own FLOWPAK streamline spacing s_gap (the `data-gap` attribute, canonical units);
  // 0: the run's.
  double gap = 0.0;
};

}  // namespace pak
