#pragma once
// Which top-level groups of an element file are layers of one drawing (OpenMoji's `color`,
// `skin`, `line` groups; Inkscape layers) and which are separate elements of a library file.
// Layers of one drawing lie over or against each other; a library lays its elements out with
// space between them.
#include <vector>

#include "pak/io/svg_reader.hpp"

namespace pak {

// The document's top-level groups gathered into elements: groups that are layers of one
// drawing, directly or through others, make one element. Two groups are layers of one drawing
// when the boxes of what they paint overlap or touch (a flag's stripes abut), or when both are
// Inkscape layers. Each entry holds the SvgShape::topGroup values of one
// element (-1: the shapes outside every group), in document order; entries are in the order of
// their first group. Groups that paint nothing are entries of their own, unless the painting
// groups make one drawing: then every group is in it (a spine layer stays with its art).
std::vector<std::vector<int>> drawingsOfGroups(const SvgDocument& document);

}  // namespace pak
