#include "flow/arclength_frame.hpp"

#include <algorithm>
#include <cmath>

#include "pak/error.hpp"

namespace pak::flow_detail {

ArclengthFrame::ArclengthFrame(const Polyline& line, const std::string& where) {
  for (Vec2 p : line) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw InputError(where, "the streamline has a non-finite point");
    if (points_.empty() || distance(points_.back(), p) > 0.0) points_.push_back(p);
  }
  if (points_.size() < 2) throw InputError(where, "the streamline needs two distinct points");
  cumulative_.assign(points_.size(), 0.0);
  for (std::size_t k = 0; k + 1 < points_.size(); ++k) {
    Vec2 d = points_[k + 1] - points_[k];
    cumulative_[k + 1] = cumulative_[k] + pak::length(d);
    segmentTangents_.push_back(normalized(d));
  }
  const std::size_t n = points_.size();
  vertexNormals_.resize(n);
  vertexNormals_.front() = perp(segmentTangents_.front());
  vertexNormals_.back() = perp(segmentTangents_.back());
  for (std::size_t k = 1; k + 1 < n; ++k) {
    Vec2 sum = segmentTangents_[k - 1] + segmentTangents_[k];
    // A U-turn leaves no average direction: keep the incoming segment's normal.
    vertexNormals_[k] = lengthSquared(sum) > 1e-24 ? perp(normalized(sum)) : perp(segmentTangents_[k - 1]);
  }
}

ArclengthFrame::Sample ArclengthFrame::at(double s) const {
  if (s <= 0.0) return {points_.front() + s * segmentTangents_.front(), vertexNormals_.front()};
  if (s >= length())
    return {points_.back() + (s - length()) * segmentTangents_.back(), vertexNormals_.back()};
  // Segment k holds s: cumulative_[k] <= s < cumulative_[k + 1].
  std::size_t k = static_cast<std::size_t>(std::upper_bound(cumulative_.begin(), cumulative_.end(), s) -
                                            cumulative_.begin()) - 1;
  k = std::min(k, points_.size() - 2);
  double t = (s - cumulative_[k]) / (cumulative_[k + 1] - cumulative_[k]);
  Vec2 point = points_[k] + t * (points_[k + 1] - points_[k]);
  Vec2 blend = (1.0 - t) * vertexNormals_[k] + t * vertexNormals_[k + 1];
  Vec2 normal = lengthSquared(blend) > 1e-24 ? normalized(blend) : perp(segmentTangents_[k]);
  return {point, normal};
}

}  // namespace pak::flow_detail
