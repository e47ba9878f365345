#pragma once
// --mirror x=VALUE, shared by `pak flow` and `pak animate`: the vertical mirror line.
#include <string>

namespace pak::cli {

// The x of "x=VALUE" (input units). Throws InputError for anything else.
double parseMirror(const std::string& text);

}  // namespace pak::cli
