#include "flow/streamline_shift.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <queue>
#include <utility>

#include "pak/error.hpp"
#include "pak/geom/bezier_fit.hpp"
#include "pak/geom/clipping.hpp"
#include "pak/geom/closest_point.hpp"
#include "pak/geom/resample.hpp"
#include "sim/region_index.hpp"
#include "sim/segment_grid.hpp"

namespace pak {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kMaxOffsetSteps = 40;        // 10 g_limit to each side
constexpr double kMaxNodes = 4'000'000.0;  // refuses absurd streamline / limit ratios

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

void checkLimit(double limit) {
  if (!(limit > 0.0) || !std::isfinite(limit)) throw InputError("", "streamline shift limit must be a positive number");
}

void checkStreamline(const Polyline& line) {
  if (line.empty()) throw InputError("", "cannot shift an empty streamline");
  for (Vec2 p : line)
    if (!finite(p)) throw InputError("", "non-finite coordinate in a shifted streamline");
}

// Unit direction of the streamline leaving its first point (`atEnd`: arriving at its last
// point), from the nearest distinct vertex; zero for a streamline of one point.
Vec2 endDirection(const Polyline& line, bool atEnd) {
  const std::size_t n = line.size();
  for (std::size_t k = 1; k < n; ++k) {
    const Vec2 d = atEnd ? line[n - 1] - line[n - 1 - k] : line[k] - line[0];
    if (lengthSquared(d) > 0.0) return normalized(d);
  }
  return {};
}

// Distance along the ray origin + t·dir (t in (0, cap]) to the first crossing of a boundary
// of `region`; `cap` when there is none.
double rayHit(Vec2 origin, Vec2 dir, const Region& region, double cap) {
  double best = cap;
  auto ring = [&](const Ring& r) {
    for (std::size_t i = 0, n = r.size(); i < n; ++i) {
      const Vec2 a = r[i], b = r[(i + 1) % n];
      const Vec2 e = b - a;
      const double denominator = cross(dir, e);
      if (denominator == 0.0) continue;  // parallel: touching along an edge counts at its ends
      const Vec2 w = a - origin;
      const double t = cross(w, e) / denominator;
      const double s = cross(w, dir) / denominator;
      if (t > 0.0 && t < best && s >= 0.0 && s <= 1.0) best = t;
    }
  };
  for (const Polygon& poly : region) {
    ring(poly.outer);
    for (const Ring& h : poly.holes) ring(h);
  }
  return best;
}

Region boxRegion(const Box& box) {
  return {Polygon{{box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}}, {}}};
}

// Where the shifted streamline may go: outside `occupied` and inside `freeSpace` (an empty
// freeSpace means no bound), both clipped to a working box. `clearance` is the distance to the
// nearest boundary of either, capped at `reach`: a segment whose ends are free and whose ends'
// clearances add up to its length or more crosses no boundary (the two discs cover it).
class FreeSpaceMap {
 public:
  FreeSpaceMap(const Region& occupied, const Region& freeSpace, const Box& box, double reach) : reach_(reach) {
    const Region window = boxRegion(box);
    const double cell = std::max(reach, std::max(box.width(), box.height()) / 512.0);
    if (!occupied.empty()) {
      occupied_ = intersect(occupied, window);
      occupiedIndex_ = RegionIndex(occupied_, cell);
      occupiedBox_ = bounds(occupied_);
    }
    bounded_ = !freeSpace.empty();
    if (bounded_) {
      free_ = intersect(freeSpace, window);
      freeIndex_ = RegionIndex(free_, cell);
      freeBox_ = bounds(free_);
    }
    auto addRings = [&](const Region& region) {
      for (const Polygon& poly : region) {
        addRing(poly.outer);
        for (const Ring& h : poly.holes) addRing(h);
      }
    };
    addRings(occupied_);
    addRings(free_);
    grid_.configure(box, reach, ends_.size() / 2);
    grid_.rebuild(points_.data(), ends_.data(), ends_.size() / 2);
  }

  // RegionIndex answers points outside its region's bounds by a slow outward search; the
  // bounds test first keeps those cheap.
  bool isFree(Vec2 p) const {
    if (occupiedBox_.contains(p) && occupiedIndex_.query(p, false).inside) return false;
    if (bounded_ && !(freeBox_.contains(p) && freeIndex_.query(p, false).inside)) return false;
    return true;
  }

  double clearance(Vec2 p) const {
    double best = reach_ * reach_;
    grid_.forEachNear(p, 1, [&](int s) {
      const Vec2 q = closestPointOnSegment(p, points_[ends_[2 * s]], points_[ends_[2 * s + 1]]);
      best = std::min(best, lengthSquared(p - q));
    });
    return std::sqrt(best);
  }

 private:
  void addRing(const Ring& ring) {
    const int first = static_cast<int>(points_.size());
    const int n = static_cast<int>(ring.size());
    points_.insert(points_.end(), ring.begin(), ring.end());
    for (int k = 0; k < n; ++k) {
      ends_.push_back(first + k);
      ends_.push_back(first + (k + 1) % n);
    }
  }

  double reach_;
  bool bounded_ = false;
  Region occupied_, free_;
  RegionIndex occupiedIndex_, freeIndex_;
  Box occupiedBox_, freeBox_;  // empty boxes contain nothing
  std::vector<Vec2> points_;
  std::vector<int> ends_;
  SegmentGrid grid_;
};

// Lattice steps (along, across) ordered by length, the `count` nearest to a node (itself
// excluded); ties are broken by the step's coordinates so the order is fixed.
std::vector<std::pair<int, int>> latticeSteps(int count, int maxAlong, int maxAcross) {
  const int radius = static_cast<int>(std::ceil(std::sqrt(count / 3.0))) + 2;
  const int ra = std::min(radius, maxAlong), rc = std::min(radius, maxAcross);
  std::vector<std::pair<int, int>> steps;
  for (int di = -ra; di <= ra; ++di)
    for (int dk = -rc; dk <= rc; ++dk)
      if (di != 0 || dk != 0) steps.emplace_back(di, dk);
  std::sort(steps.begin(), steps.end(), [](auto a, auto b) {
    const int la = a.first * a.first + a.second * a.second, lb = b.first * b.first + b.second * b.second;
    return la != lb ? la < lb : a < b;
  });
  if (steps.size() > static_cast<std::size_t>(count)) steps.resize(static_cast<std::size_t>(count));
  return steps;
}

// The `count` nearest to p of positions[first, last) (ties by index).
std::vector<int> nearestNodes(Vec2 p, const std::vector<Vec2>& positions, int first, int last, int count) {
  std::vector<std::pair<double, int>> byDistance;
  for (int i = first; i < last; ++i)
    byDistance.emplace_back(lengthSquared(positions[static_cast<std::size_t>(i)] - p), i);
  const std::size_t keep = std::min(byDistance.size(), static_cast<std::size_t>(count));
  std::partial_sort(byDistance.begin(), byDistance.begin() + static_cast<std::ptrdiff_t>(keep), byDistance.end());
  std::vector<int> out;
  for (std::size_t i = 0; i < keep; ++i) out.push_back(byDistance[i].second);
  return out;
}

// Does every point and every segment of `line` stay in free space?
bool staysFree(const Polyline& line, const FreeSpaceMap& map) {
  std::vector<double> clear(line.size());
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (!map.isFree(line[i])) return false;
    clear[i] = map.clearance(line[i]);
  }
  for (std::size_t i = 1; i < line.size(); ++i)
    if (clear[i - 1] + clear[i] < distance(line[i - 1], line[i])) return false;
  return true;
}


// The node graph of thesis 3.3.6 (Figure 3.6): `rows` samples of the streamline, h apart, each
// offset across it by `columns` multiples of h (lattice node i·columns + c), then the start and
// goal nodes (the shifted endpoints).
struct NodeGraph {
  double h = 0.0;
  int rows = 0, columns = 0, kRight = 0;
  Polyline samples;
  std::vector<Vec2> normals;     // left normal per row
  std::vector<Vec2> position;    // lattice nodes, then start, then goal
  std::vector<char> usable;      // in free space
  std::vector<double> clearance; // distance to forbidden space, capped (FreeSpaceMap)
  std::vector<double> toOriginal;// D(s_i, p) of eq. 3.2
  int lattice() const { return rows * columns; }
  int start() const { return lattice(); }
  int goal() const { return lattice() + 1; }
  double offsetOf(int n) const { return (n % columns - kRight) * h; }
};

// D(s_i, p) of eq. 3.2 for the usable lattice nodes: distance to the original streamline (its
// resampling). A local search outward from the node's own sample, until a sample is more than
// the best distance plus one spacing away (exact unless the streamline curls back that close).
void computeDistancesToOriginal(NodeGraph& g, const Polyline& streamline) {
  auto segmentDistance2 = [](Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double l2 = lengthSquared(ab);
    const double t = l2 > 0.0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return lengthSquared(p - (a + ab * t));
  };
  g.toOriginal.assign(g.position.size(), 0.0);
  for (int n = 0; n < g.lattice(); ++n) {
    if (!g.usable[static_cast<std::size_t>(n)]) continue;
    const int i = n / g.columns;
    const Vec2 p = g.position[static_cast<std::size_t>(n)];
    double best = std::abs(g.offsetOf(n));
    double best2 = best * best;
    for (int dir : {-1, 1})
      for (int j = dir < 0 ? i - 1 : i; j >= 0 && j + 1 < g.rows; j += dir) {
        const Vec2 a = g.samples[static_cast<std::size_t>(j)], b = g.samples[static_cast<std::size_t>(j + 1)];
        best2 = std::min(best2, segmentDistance2(p, a, b));
        best = std::sqrt(best2);
        if (lengthSquared(p - (dir < 0 ? a : b)) > (best + g.h) * (best + g.h)) break;
      }
    g.toOriginal[static_cast<std::size_t>(n)] = best;
  }
  for (int n : {g.start(), g.goal()})
    g.toOriginal[static_cast<std::size_t>(n)] = closestPointOnPolyline(g.position[static_cast<std::size_t>(n)], streamline).distance;
}

// Edges out of the start node and into the goal node (they are not on the lattice).
struct EndLinks {
  std::vector<int> fromStart;    // node indices (the goal included when close enough)
  std::vector<char> reachesGoal; // per node: has the goal among its neighbours
};

// Dijkstra from start to goal with edge cost eq. 3.2 and the no-back-tracking rule, as
// label-setting on nodes: a node's predecessor is fixed when it is settled, and the rule uses
// that predecessor (the exact search over (node, predecessor) states would multiply the graph
// by the neighbour count). Returns the node positions from start to goal, empty if unreachable.
Polyline cheapestPath(const NodeGraph& g, const std::vector<std::pair<int, int>>& steps, const EndLinks& links,
                      const VectorField& field, double fieldSign, const ShiftOptions& options) {
  const std::size_t nodeCount = g.position.size();
  const int columns = g.columns, rows = g.rows, start = g.start(), goal = g.goal();
  std::vector<double> cost(nodeCount, kInfinity);
  std::vector<int> predecessor(nodeCount, -1);
  std::vector<char> open(g.usable);  // usable and not yet settled
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  cost[static_cast<std::size_t>(start)] = 0.0;
  queue.push({0.0, start});
  const double wf = options.fieldWeight, wd = options.distanceWeight, power = options.fieldPower;
  const double h = g.h, limit = options.limit;
  const bool cubic = power == 3.0;  // the thesis's p; std::pow would be a large share of the search
  // Per column, the lattice steps that stay within the columns, as (rows, index) offsets.
  std::vector<std::vector<std::pair<int, int>>> columnSteps(static_cast<std::size_t>(columns));
  int maxAlong = 0;
  for (int c = 0; c < columns; ++c)
    for (auto [di, dk] : steps)
      if (c + dk >= 0 && c + dk < columns) {
        columnSteps[static_cast<std::size_t>(c)].emplace_back(di, di * columns + dk);
        maxAlong = std::max(maxAlong, std::abs(di));
      }
  bool goalSettled = false;
  while (!queue.empty()) {
    const double pathCost = queue.top().first;
    const int a = queue.top().second;
    queue.pop();
    const std::size_t ua = static_cast<std::size_t>(a);
    if (!open[ua]) continue;
    open[ua] = 0;
    if (a == goal) {
      goalSettled = true;
      break;
    }
    const Vec2 pa = g.position[ua];
    const bool hasIncoming = predecessor[ua] >= 0;
    const Vec2 incoming = hasIncoming ? pa - g.position[static_cast<std::size_t>(predecessor[ua])] : Vec2{};
    const Vec2 v = field.at(pa) * fieldSign;
    const double clearanceA = g.clearance[ua];
    // Eq. 3.2 per unit of path (see docs/flowpak-shift.md): w = |e|/h (w_f (1 - f^p) + w_d D / g_limit).
    const double distanceTerm = wd * g.toOriginal[ua] / limit;
    auto relax = [&](int b) {
      const std::size_t ub = static_cast<std::size_t>(b);
      if (!open[ub]) return;
      const Vec2 e = g.position[ub] - pa;
      if (hasIncoming && dot(incoming, e) <= 0.0) return;  // turning by 90° or more
      const double len2 = lengthSquared(e), reach = clearanceA + g.clearance[ub];
      if (len2 <= 0.0 || reach * reach < len2) return;  // the edge might cross a boundary
      const double len = std::sqrt(len2);
      const double f = std::clamp(dot(e, v) / len, 0.0, 1.0);
      const double fp = cubic ? f * f * f : std::pow(f, power);
      const double w = len / h * (wf * (1.0 - fp) + distanceTerm);
      if (pathCost + w < cost[ub]) {
        cost[ub] = pathCost + w;
        predecessor[ub] = a;
        queue.push({cost[ub], b});
      }
    };
    if (a == start) {
      for (int b : links.fromStart) relax(b);
      continue;
    }
    const int i = a / columns;
    const auto& candidates = columnSteps[static_cast<std::size_t>(a % columns)];
    if (i >= maxAlong && i + maxAlong < rows) {
      for (auto [di, delta] : candidates) relax(a + delta);
    } else {
      for (auto [di, delta] : candidates)
        if (i + di >= 0 && i + di < rows) relax(a + delta);
    }
    if (links.reachesGoal[ua]) relax(goal);
  }
  Polyline path;
  if (!goalSettled) return path;
  for (int n = goal; n >= 0; n = predecessor[static_cast<std::size_t>(n)]) path.push_back(g.position[static_cast<std::size_t>(n)]);
  std::reverse(path.begin(), path.end());
  return path;
}

// Cubic Béziers [Sch90] through the node path, flattened. A fit that strays out of free space
// is retried tighter, and the node path itself (whose edges were checked) is the last resort.
Polyline smoothWithinFreeSpace(const Polyline& path, const FreeSpaceMap& map, double tolerance) {
  for (int attempt = 0; attempt < 3; ++attempt, tolerance *= 0.5) {
    // The path turns by less than 90° at every node, so a 90° corner angle smooths it all.
    // Splitting at the worst point, as the streamline shift was measured with (docs/flowpak.md).
    Polyline smooth =
        flatten(fitCubicBeziers(path, tolerance, 0.5 * std::numbers::pi, FitSpans::SplitAtWorst), 0.25 * tolerance);
    if (staysFree(smooth, map)) return smooth;
  }
  return path;
}
}  // namespace

std::array<Vec2, 2> shiftedEndpoints(const Polyline& streamline, const Region& occupied, const Region& freeSpace,
                                     double limit) {
  checkStreamline(streamline);
  checkLimit(limit);
  std::array<Vec2, 2> ends{streamline.front(), streamline.back()};
  // Rays stop at the first boundary of either region; one that meets none ends at `cap`, so
  // open space on one side (far from everything) reads as "a lot of room".
  const double cap = 10.0 * limit;
  for (int e = 0; e < 2; ++e) {
    const Vec2 direction = endDirection(streamline, e == 1);
    if (direction == Vec2{}) continue;
    const Vec2 left = perp(direction);
    auto hit = [&](Vec2 dir) {
      double t = rayHit(ends[e], dir, occupied, cap);
      return std::min(t, rayHit(ends[e], dir, freeSpace, cap));
    };
    // Midpoint of the free segment along the normal, as a signed offset to the left.
    const double middle = 0.5 * (hit(left) - hit(-left));
    ends[e] += left * std::clamp(middle, -limit, limit);
  }
  return ends;
}

Polyline shiftStreamline(const Polyline& streamline, const VectorField& field, const Region& occupied,
                         const Region& freeSpace, double maxLeft, double maxRight, const ShiftOptions& options) {
  checkStreamline(streamline);
  const double limit = options.limit;
  checkLimit(limit);
  if (!(maxLeft >= 0.0) || !(maxRight >= 0.0) || !std::isfinite(maxLeft) || !std::isfinite(maxRight))
    throw InputError("", "streamline shift widths must be non-negative numbers");
  if (!(options.fieldWeight >= 0.0) || !(options.distanceWeight >= 0.0) || !(options.fieldPower > 0.0) ||
      !std::isfinite(options.fieldWeight) || !std::isfinite(options.distanceWeight) ||
      !std::isfinite(options.fieldPower) || options.neighbours < 1 || !(options.fitTolerance >= 0.0) ||
      !std::isfinite(options.fitTolerance))
    throw InputError("", "invalid streamline shift options");
  if (polylineLength(streamline) <= 0.0) return streamline;

  // Thesis 3.3.6: nodes every 0.25 g_limit along the streamline and across it.
  NodeGraph g;
  g.h = 0.25 * limit;
  const double h = g.h;
  g.samples = resamplePolyline(streamline, h);
  g.rows = static_cast<int>(g.samples.size());
  // Offsets beyond 10 g_limit are capped: there eq. 3.2's distance term alone (w_d D / g_limit
  // per step, ≥ 1 with w_d = 0.1) outweighs the largest field term, so paths do not go there
  // unless forced, and a very wide blob would otherwise make the graph huge.
  const double widest = kMaxOffsetSteps * h;
  g.kRight = static_cast<int>(std::floor(std::min(maxRight, widest) / h + 1e-9));
  const int kLeft = static_cast<int>(std::floor(std::min(maxLeft, widest) / h + 1e-9));
  g.columns = kLeft + g.kRight + 1;
  if (static_cast<double>(g.rows) * g.columns > kMaxNodes)
    throw InputError("", "streamline is too long for its shift limit (node graph over 4 million nodes)");
  const int lattice = g.lattice();
  g.position.resize(static_cast<std::size_t>(lattice) + 2);
  g.normals.resize(static_cast<std::size_t>(g.rows));
  for (int i = 0; i < g.rows; ++i) {
    const Vec2 normal = perp(normalized(g.samples[static_cast<std::size_t>(std::min(i + 1, g.rows - 1))] -
                                        g.samples[static_cast<std::size_t>(std::max(i - 1, 0))]));
    g.normals[static_cast<std::size_t>(i)] = normal;
    for (int c = 0; c < g.columns; ++c)
      g.position[static_cast<std::size_t>(i * g.columns + c)] =
          g.samples[static_cast<std::size_t>(i)] + normal * ((c - g.kRight) * h);
  }
  std::array<Vec2, 2> ends = shiftedEndpoints(streamline, occupied, freeSpace, limit);

  // The thesis examines each node's 150 nearest nodes. The nodes form a lattice of spacing h,
  // so those are (up to the lattice's bending) the nearest lattice steps: no k-d tree needed.
  const std::vector<std::pair<int, int>> steps = latticeSteps(options.neighbours, g.rows - 1, g.columns - 1);
  double stepReach = h;
  for (auto [di, dk] : steps) stepReach = std::max(stepReach, h * std::sqrt(double(di * di + dk * dk)));
  auto nearestReach = [&](const std::vector<int>& nearest, Vec2 end) {
    return nearest.empty() ? 0.0 : distance(end, g.position[static_cast<std::size_t>(nearest.back())]);
  };
  // An end's nearest nodes are searched among the rows at its end of the lattice: enough rows
  // to hold `neighbours` nodes, plus the 8 rows an end may slide back, plus a margin.
  const int endRows = std::min(g.rows, (options.neighbours + g.columns - 1) / g.columns + 12);
  auto nearestToEnd = [&](int e, Vec2 p) {
    return e == 0 ? nearestNodes(p, g.position, 0, endRows * g.columns, options.neighbours)
                  : nearestNodes(p, g.position, (g.rows - endRows) * g.columns, lattice, options.neighbours);
  };
  std::vector<int> startNearest = nearestToEnd(0, ends[0]);
  std::vector<int> goalNearest = nearestToEnd(1, ends[1]);
  const double endReach = std::max(nearestReach(startNearest, ends[0]), nearestReach(goalNearest, ends[1]));

  Box box;
  for (int n = 0; n < lattice; ++n) box.add(g.position[static_cast<std::size_t>(n)]);
  box.add(ends[0]);
  box.add(ends[1]);
  const double reach = 0.5 * std::max(stepReach, endReach) + h;
  box.add(box.min - Vec2{reach + 2 * h, reach + 2 * h});
  box.add(box.max + Vec2{reach + 2 * h, reach + 2 * h});
  const FreeSpaceMap map(occupied, freeSpace, box, reach);

  // A streamline extended to its blob ends on a boundary, so a shifted end may lie on or just
  // beyond it: such an end slides back along the streamline (same normal offset) by up to
  // 2 g_limit until it is free. The pipeline re-extends the result to the blob anyway.
  for (int e = 0; e < 2; ++e) {
    if (map.isFree(ends[e])) continue;
    const std::size_t endRow = e == 0 ? 0 : static_cast<std::size_t>(g.rows - 1);
    const double shift = dot(ends[e] - g.samples[endRow], g.normals[endRow]);
    for (int r = 1; r <= std::min(g.rows - 1, 8); ++r) {
      const std::size_t row = static_cast<std::size_t>(e == 0 ? r : g.rows - 1 - r);
      const Vec2 candidate = g.samples[row] + g.normals[row] * shift;
      if (map.isFree(candidate)) {
        ends[e] = candidate;
        (e == 0 ? startNearest : goalNearest) = nearestToEnd(e, candidate);
        break;
      }
    }
  }
  g.position[static_cast<std::size_t>(g.start())] = ends[0];
  g.position[static_cast<std::size_t>(g.goal())] = ends[1];

  const std::size_t nodeCount = g.position.size();
  g.usable.resize(nodeCount);
  g.clearance.assign(nodeCount, 0.0);
  for (std::size_t n = 0; n < nodeCount; ++n) {
    g.usable[n] = map.isFree(g.position[n]);
    if (g.usable[n]) g.clearance[n] = map.clearance(g.position[n]);
  }
  if (!g.usable[static_cast<std::size_t>(g.start())] || !g.usable[static_cast<std::size_t>(g.goal())]) return streamline;
  computeDistancesToOriginal(g, streamline);

  // Lattice nodes that have the goal among their nearest nodes (or it among the goal's); the
  // start links to its nearest nodes. Links longer than 2 reach fail the clearance test
  // (conservative only).
  EndLinks links;
  links.reachesGoal.assign(nodeCount, 0);
  for (int n : goalNearest) links.reachesGoal[static_cast<std::size_t>(n)] = 1;
  for (int n = 0; n < lattice; ++n)
    if (distance(g.position[static_cast<std::size_t>(n)], ends[1]) <= stepReach) links.reachesGoal[static_cast<std::size_t>(n)] = 1;
  links.fromStart = startNearest;
  const double endLinks = std::max(nearestReach(startNearest, ends[0]), nearestReach(goalNearest, ends[1]));
  if (distance(ends[0], ends[1]) <= endLinks) links.fromStart.push_back(g.goal());

  // The field's sense along this streamline (a 1-RoSy field may run against how it was stored).
  double sense = 0.0;
  for (int i = 0; i + 1 < g.rows; ++i)
    sense += dot(field.at(g.samples[static_cast<std::size_t>(i)]),
                 g.samples[static_cast<std::size_t>(i + 1)] - g.samples[static_cast<std::size_t>(i)]);
  const double fieldSign = sense < 0.0 ? -1.0 : 1.0;

  const Polyline path = cheapestPath(g, steps, links, field, fieldSign, options);
  if (path.empty()) return streamline;
  return smoothWithinFreeSpace(path, map, options.fitTolerance > 0.0 ? options.fitTolerance : 0.25 * limit);
}

}  // namespace pak
