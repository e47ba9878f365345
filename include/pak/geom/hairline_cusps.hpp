#pragma once
// Hairline cusps: a filled ring that comes within a hair of itself between edges that share no
// vertex (an ear drawn touching the head, a slit or spike thinner than a pixel). Drawn, it
// looks like one clean outline; bent by a mesh, its two sides cross at once.
#include <vector>

#include "pak/geom/art.hpp"

namespace pak {

// Whether two edges of the closed ring come closer than `width`, and ten times closer than the
// way along the ring between them (a slit or a spike sharper than 11°; not a curve or a corner).
bool ringHasHairline(const Ring& ring, double width);

// Each filled, unstroked shape with a ring that has a hairline narrower than `width` (and none
// drawn crossing itself, which is left to the artist) is redrawn
// as its fill closed and then opened by width / 2 (slits filled, spikes trimmed): the same
// picture at any useful zoom, with rings that do not touch themselves. Returns how many shapes
// changed.
int removeHairlineCusps(std::vector<Shape>& art, double width);

}  // namespace pak
