#include "pak/io/svg_shape.hpp"

namespace pak {

Box bounds(const std::vector<SvgShape>& shapes) {
  Box box;
  for (const SvgShape& shape : shapes) box.add(bounds(shape));
  return box;
}

}  // namespace pak
