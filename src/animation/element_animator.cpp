#include "animation/element_animator.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "pak/error.hpp"

namespace pak {

ElementAnimator::ElementAnimator(const TriMesh& mesh, const std::vector<ElementHandle>& handles,
                                 const ElementAnimation& animation, Vec2 fileOrigin, double fileScale, bool periodic)
    : rest_(mesh.vertices), animation_(animation), periodic_(periodic) {
  for (PointKey& key : animation_.translation) key.value = key.value * fileScale;

  // Each moving handle drives the mesh vertex nearest to it. Handles the script does not
  // move stay where they are (pinned), so a single moving handle bends the shape instead of
  // dragging it.
  std::vector<int> pinned;
  for (ElementAnimation::HandleTrack& track : animation_.handles) {
    const ElementHandle* handle = nullptr;
    for (const ElementHandle& h : handles)
      if (h.name == track.name) handle = &h;
    if (!handle) throw InputError("", "the animation moves handle '" + track.name + "', which the element has no <circle id=\"handle-" + track.name + "\"> for");
    for (PointKey& key : track.offset) key.value = key.value * fileScale;
  }
  auto nearestVertex = [&](Vec2 p) {
    int best = 0;
    double bestD = std::numeric_limits<double>::infinity();
    for (std::size_t v = 0; v < rest_.size(); ++v)
      if (double d = lengthSquared(rest_[v] - p); d < bestD) bestD = d, best = static_cast<int>(v);
    return best;
  };
  if (animation_.handles.empty()) return;
  std::vector<int> vertices;
  for (const ElementAnimation::HandleTrack& track : animation_.handles) {
    for (const ElementHandle& h : handles)
      if (h.name == track.name) {
        Vec2 p = (h.position - fileOrigin) * fileScale;
        int v = nearestVertex(p);
        for (int used : vertices)
          if (used == v) throw InputError("", "handles '" + track.name + "' and another one fall on the same mesh vertex; move them apart");
        vertices.push_back(v);
        handleRest_.push_back(rest_[v]);
      }
  }
  for (const ElementHandle& h : handles) {
    bool moved = false;
    for (const ElementAnimation::HandleTrack& track : animation_.handles) moved = moved || track.name == h.name;
    if (moved) continue;
    int v = nearestVertex((h.position - fileOrigin) * fileScale);
    bool duplicate = false;
    for (int used : vertices) duplicate = duplicate || used == v;
    if (duplicate) continue;
    vertices.push_back(v);
    handleRest_.push_back(rest_[v]);
  }
  arap_.emplace(mesh, vertices);
}

void ElementAnimator::shapeAt(double t, std::vector<Vec2>& out) const {
  if (arap_) {
    std::vector<Vec2> targets = handleRest_;
    for (std::size_t k = 0; k < animation_.handles.size(); ++k)
      targets[k] = handleRest_[k] + sampleTrack(animation_.handles[k].offset, t, Vec2{}, periodic_);
    arap_->deform(targets, out);
  } else {
    out = rest_;
  }
  const double scale = sampleTrack(animation_.scale, t, 1.0, periodic_);
  // y points down: a counter-clockwise turn on screen is a negative angle in these axes.
  const double angle = -sampleTrack(animation_.rotation, t, 0.0, periodic_) * std::numbers::pi / 180.0;
  const Vec2 move = sampleTrack(animation_.translation, t, Vec2{}, periodic_);
  const double c = std::cos(angle) * scale, s = std::sin(angle) * scale;
  for (Vec2& p : out) p = Vec2{c * p.x - s * p.y, s * p.x + c * p.y} + move;
}

}  // namespace pak
