#pragma once
// Source markup an output copies as it is (a scene's `fixed` layer): Pak never re-formats it.
#include <string>
#include <utility>
#include <vector>

namespace pak {

// Well-formed XML elements, with the definitions they reference and the namespaces their
// names use.
struct RawMarkup {
  std::string content;  // elements, byte for byte from the input, in a <g> placing them
  std::string defs;     // the gradients, clip paths … the content references, byte for byte
  std::vector<std::pair<std::string, std::string>> namespaces;  // prefix, URI (for xmlns:prefix)
  bool empty() const { return content.empty(); }
};

}  // namespace pak
