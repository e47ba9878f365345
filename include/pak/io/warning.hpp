#pragma once
// Something a reader skipped or reinterpreted in an input file, for the user to see. Only
// the readers warn: the core takes scenes and art already read and reports bad input by
// throwing InputError.
#include <string>

namespace pak {

struct Warning {
  std::string where;    // file and element id or line
  std::string message;  // what was skipped and why
  // The document's top-level group it is about (SvgShape::topGroup), -1 for none: a scene
  // that copies that group to its outputs as written drops what the reader said of it.
  int topGroup = -1;
};

}  // namespace pak
