#pragma once
// What the packers consume: a scene (containers, fixed elements, guides, spines) and a
// library of elements: geometry and paint. Built by src/io from files, which also keeps what
// only the output needs (pak/io/scene_layout.hpp) and the readers' warnings; the core never
// reads files itself.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "pak/geom/art.hpp"
#include "pak/geom/polygon.hpp"

namespace pak {

struct ContainerPart;

struct Scene {
  std::string source;               // the file (or tile) it came from, for messages
  Region container;                 // union of the container shapes, holes subtracted
  // The separate containers (disjoint parts of `container`, each with its holes, or one per
  // element of a previous packing): every element stays in the one it was seeded in.
  // Empty: each polygon of `container` is one container, filled from the run's library.
  std::vector<ContainerPart> containers;
  std::vector<Shape> fixed;         // fixed elements: obstacles, and drawn in the output
  std::vector<Polyline> guides;     // FLOWPAK direction strokes
  std::vector<Polyline> spines;     // FLOWPAK fixed spines
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
