#pragma once
// Preferred orientations (thesis 4.5, torsional force eq. 4.6, Figure 4.11): the rest angle
// an element is seeded with and pulled back to, either one angle for all or a field that
// maps position to an angle.
#include <string>

#include "pak/geom/vec2.hpp"

namespace pak {

enum class OrientationMode {
  Random,   // random seeded angle, no preferred orientation (the default)
  Upright,  // seeded at the element's drawn angle (0) and held there
  Field,    // seeded at and held to the angle of an OrientationField at the element's centre
};

// A linear ramp of the rest angle along one axis of the container's bounding box: `from`
// degrees at its left (x) or top (y) edge to `to` degrees at the opposite edge. Angles turn
// as SVG's rotate() does: positive is clockwise on screen (y points down).
struct OrientationField {
  char axis = 'x';         // 'x' or 'y'
  double fromDegrees = 0.0;
  double toDegrees = 180.0;
};

// "x:0:180" or "y:-45:45" → the field; throws InputError (--orientation-field) otherwise.
OrientationField parseOrientationField(const std::string& text);
// "upright", "random" or "field" → the mode; throws InputError (--orientation) otherwise.
OrientationMode parseOrientationMode(const std::string& text);
const char* toString(OrientationMode mode);

// The field in a frame (the simulation's canonical one): the angle, in radians, at a point.
// Cheap enough to evaluate per mesh per step.
struct OrientationRamp {
  bool active = false;
  int axis = 0;               // 0: x, 1: y
  double low = 0.0, span = 1.0;   // the box's extent along the axis
  double from = 0.0, turn = 0.0;  // radians at `low`, and the change to `low + span`
  static OrientationRamp over(const OrientationField& field, Vec2 boxMin, Vec2 boxMax);
  double angleAt(Vec2 p) const {
    double t = ((axis == 0 ? p.x : p.y) - low) / span;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return from + turn * t;
  }
};

}  // namespace pak
