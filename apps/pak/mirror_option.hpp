#pragma once
// --mirror, shared by `pak flow` and `pak animate`: the mirror line of a symmetric packing.
#include <string>

#include "pak/geom/mirror_line.hpp"

namespace pak::cli {

// "x=VALUE" (vertical: the part left of it is packed), "y=VALUE" (horizontal: the part above
// it) or "X1,Y1,X2,Y2" (through two points: the part on the left of a walk from the first to
// the second, as seen on screen), in input units. Throws InputError for anything else.
MirrorLine parseMirror(const std::string& text);

}  // namespace pak::cli
