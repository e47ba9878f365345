#pragma once
// Warnings as the user reads them: "<where>: <message>" on one line (oneLine), each place and
// message once, in order. The CLI prints them after "pak: warning: "; the Python module gives
// each as a pak.InputWarning. (An element carries its document's warnings, so the elements of
// one file repeat them.)
#include <string>
#include <vector>

#include "pak/io/warning.hpp"

namespace pak {

std::vector<std::string> warningLines(const std::vector<Warning>& warnings);

}  // namespace pak
