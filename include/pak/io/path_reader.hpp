#pragma once
// Reads the original RepulsionPak `.path` text format (grammar: shared data README).
#include <string>

#include "pak/io/svg_reader.hpp"

namespace pak {

// Returns the paths as shapes in an SvgDocument so the rest of Pak treats both formats alike:
// boundary paths (type 0) get layer "", focal paths (type 2) layer "fixed", holes (type 7)
// layer "holes", skeletons (6) "spines", fields (3) "guides". Colours come from the colour
// lines (background = fill, foreground = stroke); a path without colours is filled black.
// Throws InputError naming the line for malformed input.
SvgDocument readPathFile(const std::string& path);
SvgDocument readPathString(const std::string& text, const std::string& name);

}  // namespace pak
