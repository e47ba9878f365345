#include "pak/repulsion/orientation.hpp"

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "pak/error.hpp"

namespace pak {

namespace {

bool parseNumber(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value);
}

}  // namespace

OrientationField parseOrientationField(const std::string& text) {
  const std::string usage = "'" + text + "' is not AXIS:FROM:TO (AXIS x or y, angles in degrees, e.g. x:0:180)";
  std::size_t first = text.find(':');
  std::size_t second = first == std::string::npos ? first : text.find(':', first + 1);
  if (second == std::string::npos || text.find(':', second + 1) != std::string::npos) throw InputError("--orientation-field", usage);
  OrientationField field;
  std::string axis = text.substr(0, first);
  if (axis != "x" && axis != "y" && axis != "X" && axis != "Y") throw InputError("--orientation-field", usage);
  field.axis = static_cast<char>(axis[0] | 0x20);
  if (!parseNumber(text.substr(first + 1, second - first - 1), field.fromDegrees) ||
      !parseNumber(text.substr(second + 1), field.toDegrees) || std::abs(field.fromDegrees) > 1e6 ||
      std::abs(field.toDegrees) > 1e6)
    throw InputError("--orientation-field", usage);
  return field;
}

OrientationMode parseOrientationMode(const std::string& text) {
  if (text == "random") return OrientationMode::Random;
  if (text == "upright") return OrientationMode::Upright;
  if (text == "field") return OrientationMode::Field;
  throw InputError("--orientation", "'" + text + "' is not one of random, upright, field");
}

const char* toString(OrientationMode mode) {
  switch (mode) {
    case OrientationMode::Random: return "random";
    case OrientationMode::Upright: return "upright";
    case OrientationMode::Field: return "field";
  }
  return "?";
}

OrientationRamp OrientationRamp::over(const OrientationField& field, Vec2 boxMin, Vec2 boxMax) {
  OrientationRamp ramp;
  ramp.active = true;
  ramp.axis = field.axis == 'y' ? 1 : 0;
  ramp.low = ramp.axis == 0 ? boxMin.x : boxMin.y;
  double span = ramp.axis == 0 ? boxMax.x - boxMin.x : boxMax.y - boxMin.y;
  ramp.span = span > 0.0 ? span : 1.0;
  constexpr double kRadians = std::numbers::pi / 180.0;
  ramp.from = field.fromDegrees * kRadians;
  ramp.turn = (field.toDegrees - field.fromDegrees) * kRadians;
  return ramp;
}

}  // namespace pak
