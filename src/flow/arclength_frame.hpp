#pragma once
// A polyline parametrised by arclength, with a left normal that varies smoothly along it:
// the frame a skeletal stroke (3.3.5) bends along and a blob's LR function (3.3.4) is
// measured in. Vertex normals are the perpendiculars of the averaged adjacent unit tangents,
// interpolated (and renormalised) along each segment, so that a curved streamline does not
// tear the art apart at its vertices. Private to src/flow.
#include <string>
#include <vector>

#include "pak/geom/polygon.hpp"

namespace pak::flow_detail {

class ArclengthFrame {
 public:
  // Zero-length segments are dropped; fewer than two distinct points throw InputError
  // (`where` names the caller in the message).
  ArclengthFrame(const Polyline& line, const std::string& where);

  double length() const { return cumulative_.back(); }

  struct Sample {
    Vec2 point;
    Vec2 normal;  // unit, left of the direction of travel
  };
  // The point at arclength s. Beyond either end the frame continues straight along the end
  // segment with the end's normal (elements whose art overhangs their outline stay whole).
  Sample at(double s) const;

 private:
  std::vector<Vec2> points_;
  std::vector<double> cumulative_;     // arclength at each point
  std::vector<Vec2> vertexNormals_;
  std::vector<Vec2> segmentTangents_;  // unit
};

}  // namespace pak::flow_detail
