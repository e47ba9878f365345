#pragma once
// Something a reader skipped or reinterpreted in an input file, for the user to see. Only
// the readers warn: the core takes scenes and art already read and reports bad input by
// throwing InputError.
#include <string>

namespace pak {

struct Warning {
  std::string where;    // file and element id or line
  std::string message;  // what was skipped and why
};

}  // namespace pak
