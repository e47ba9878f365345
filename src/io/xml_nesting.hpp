#pragma once
// How deep the elements of an XML text nest, found by a flat scan before any recursive parser
// (rapidxml, SVG++) sees the text: a file of thousands of nested <g> would overflow their stack.
#include <cstddef>
#include <string>
#include <string_view>

namespace pak {

// Deeper than any drawing program writes (Inkscape layers and groups nest a few dozen deep),
// and shallow enough that the recursive readers stay far inside a thread's stack.
constexpr int kMaxXmlNesting = 256;

// Throws InputError(`file`:line, …) at the first element nested deeper than `maxDepth`.
// Malformed markup is left to the parser, which reports it with its own words.
void checkXmlNesting(std::string_view text, const std::string& file, int maxDepth = kMaxXmlNesting);

}  // namespace pak
