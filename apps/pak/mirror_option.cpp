#include "mirror_option.hpp"

#include <cmath>
#include <cstdio>

#include "pak/error.hpp"

namespace pak::cli {

MirrorLine parseMirror(const std::string& text) {
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0;
  char extra = 0;
  auto finite = [](std::initializer_list<double> values) {
    for (double v : values)
      if (!std::isfinite(v)) return false;
    return true;
  };
  if (std::sscanf(text.c_str(), " x = %lf %c", &a, &extra) == 1 && finite({a})) return MirrorLine::vertical(a);
  if (std::sscanf(text.c_str(), " y = %lf %c", &a, &extra) == 1 && finite({a})) return MirrorLine::horizontal(a);
  if (std::sscanf(text.c_str(), " %lf , %lf , %lf , %lf %c", &a, &b, &c, &d, &extra) == 4 && finite({a, b, c, d})) {
    if (a == c && b == d) throw InputError("--mirror", "the line's two points are the same point");
    return MirrorLine{{a, b}, {c, d}};
  }
  throw InputError("--mirror", "expects x=VALUE (a vertical line), y=VALUE (a horizontal one) or X1,Y1,X2,Y2 (the line "
                               "through two points), in input units; got \"" + text + "\"");
}

}  // namespace pak::cli
