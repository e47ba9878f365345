#include "mirror_option.hpp"

#include <cmath>
#include <cstdio>

#include "pak/error.hpp"

namespace pak::cli {

double parseMirror(const std::string& text) {
  double x = 0.0;
  char extra = 0;
  if (std::sscanf(text.c_str(), " x = %lf %c", &x, &extra) != 1 || !std::isfinite(x))
    throw InputError("--mirror", "expects x=VALUE (the vertical mirror line, input units), got \"" + text + "\"");
  return x;
}

}  // namespace pak::cli
