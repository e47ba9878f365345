#include "pak/geom/bezier_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "pak/error.hpp"
#include "pak/geom/closest_point.hpp"
#include "pak/geom/resample.hpp"

// Schneider's curve fitting [Sch90]: chord-length parameters, a least-squares solve for the
// two inner control points along fixed end tangents, a few Newton–Raphson corrections of the
// parameters, and a split at the worst point when the error stays above tolerance.
namespace pak {
namespace {

constexpr int kReparameterisations = 10;

Vec2 evaluate(const CubicBezier& c, double t) {
  const double s = 1.0 - t;
  return c[0] * (s * s * s) + c[1] * (3.0 * s * s * t) + c[2] * (3.0 * s * t * t) + c[3] * (t * t * t);
}
Vec2 firstDerivative(const CubicBezier& c, double t) {
  const double s = 1.0 - t;
  return (c[1] - c[0]) * (3.0 * s * s) + (c[2] - c[1]) * (6.0 * s * t) + (c[3] - c[2]) * (3.0 * t * t);
}
Vec2 secondDerivative(const CubicBezier& c, double t) {
  return (c[2] - c[1] * 2.0 + c[0]) * (6.0 * (1.0 - t)) + (c[3] - c[2] * 2.0 + c[1]) * (6.0 * t);
}

void checkInput(const std::vector<Vec2>& points, double tolerance) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw InputError("", "Bézier fit tolerance must be a positive number");
  for (Vec2 p : points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw InputError("", "non-finite coordinate in a fitted path");
}

// Drops consecutive duplicates (closed rings also lose a repeated closing vertex).
std::vector<Vec2> withoutDuplicates(const std::vector<Vec2>& points, bool closed) {
  std::vector<Vec2> out;
  out.reserve(points.size());
  for (Vec2 p : points)
    if (out.empty() || !(p == out.back())) out.push_back(p);
  if (closed)
    while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

// Straight segment as a cubic (inner points at thirds).
CubicBezier straight(Vec2 a, Vec2 b) { return {a, a + (b - a) / 3.0, a + (b - a) * (2.0 / 3.0), b}; }

// Chord-length parameters of points[first..last], from 0 to 1.
std::vector<double> chordLengthParameters(const std::vector<Vec2>& p, std::size_t first, std::size_t last) {
  std::vector<double> u(last - first + 1, 0.0);
  for (std::size_t i = first + 1; i <= last; ++i) u[i - first] = u[i - first - 1] + distance(p[i], p[i - 1]);
  const double total = u.back();
  for (double& v : u) v = total > 0.0 ? v / total : 0.0;
  return u;
}

// Least-squares inner control points along the unit tangents t1 (leaving the first point) and
// t2 (leaving the last point backwards). Falls back to the thirds heuristic (Wu–Barsky) when
// the system is singular or gives a non-positive length, and with `capHandles` when a handle
// is longer than the chord: that makes a loop or a zigzag back along the chord (three points
// fit exactly by a wild curve); the thirds then fail the error test and the span splits.
CubicBezier leastSquaresCurve(const std::vector<Vec2>& p, std::size_t first, std::size_t last,
                              const std::vector<double>& u, Vec2 t1, Vec2 t2, bool capHandles) {
  const Vec2 a = p[first], b = p[last];
  double c00 = 0.0, c01 = 0.0, c11 = 0.0, x0 = 0.0, x1 = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double t = u[i], s = 1.0 - t;
    const double b0 = s * s * s, b1 = 3.0 * s * s * t, b2 = 3.0 * s * t * t, b3 = t * t * t;
    const Vec2 a1 = t1 * b1, a2 = t2 * b2;
    c00 += dot(a1, a1);
    c01 += dot(a1, a2);
    c11 += dot(a2, a2);
    const Vec2 rest = p[first + i] - (a * (b0 + b1) + b * (b2 + b3));
    x0 += dot(a1, rest);
    x1 += dot(a2, rest);
  }
  const double det = c00 * c11 - c01 * c01;
  double alphaA = 0.0, alphaB = 0.0;
  if (std::abs(det) > 1e-12 * std::max(1.0, c00 * c11)) {
    alphaA = (x0 * c11 - x1 * c01) / det;
    alphaB = (c00 * x1 - c01 * x0) / det;
  }
  const double chord = distance(a, b);
  const double epsilon = 1e-6 * chord;
  const bool tooLong = capHandles && (alphaA > chord || alphaB > chord);
  if (!(alphaA > epsilon) || !(alphaB > epsilon) || !std::isfinite(alphaA) || !std::isfinite(alphaB) || tooLong)
    alphaA = alphaB = chord / 3.0;
  return {a, a + t1 * alphaA, b + t2 * alphaB, b};
}

double distanceToSegment(Vec2 q, Vec2 a, Vec2 b) { return distance(q, closestPointOnSegment(q, a, b)); }

// Largest squared distance between a point and the curve at its parameter, over the interior
// points; `worst` receives the index of that point.
double maxSquaredError(const std::vector<Vec2>& p, std::size_t first, std::size_t last, const CubicBezier& c,
                       const std::vector<double>& u, std::size_t& worst) {
  double best = 0.0;
  worst = (first + last) / 2;
  for (std::size_t i = first + 1; i < last; ++i) {
    const double d = lengthSquared(evaluate(c, u[i - first]) - p[i]);
    if (d > best) { best = d; worst = i; }
  }
  return best;
}

// Whether the curve strays further than `tolerance` from the polyline p[first..last] anywhere:
// Schneider checks the points only, and between them a curve can bow off the polygon.
bool bowsOff(const CubicBezier& c, const std::vector<Vec2>& p, std::size_t first, std::size_t last, double tolerance) {
  const double tolerance2 = tolerance * tolerance;
  for (Vec2 q : flatten({c}, 0.1 * tolerance)) {
    double best2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = first; i < last && best2 > tolerance2; ++i)
      best2 = std::min(best2, lengthSquared(q - closestPointOnSegment(q, p[i], p[i + 1])));
    if (best2 > tolerance2) return true;
  }
  return false;
}

// One Newton–Raphson step per parameter towards the curve's closest point to its data point.
void reparameterise(const std::vector<Vec2>& p, std::size_t first, const CubicBezier& c, std::vector<double>& u) {
  for (std::size_t i = 0; i < u.size(); ++i) {
    const Vec2 q = evaluate(c, u[i]) - p[first + i];
    const Vec2 d1 = firstDerivative(c, u[i]), d2 = secondDerivative(c, u[i]);
    const double numerator = dot(q, d1);
    const double denominator = dot(d1, d1) + dot(q, d2);
    if (std::abs(denominator) > 1e-300) {
      const double next = u[i] - numerator / denominator;
      if (std::isfinite(next)) u[i] = std::clamp(next, 0.0, 1.0);
    }
  }
}

// The tangent through point i, from its neighbours (pointing backwards, towards i-1).
Vec2 centreTangent(const std::vector<Vec2>& p, std::size_t i) {
  Vec2 t = normalized(p[i - 1] - p[i + 1]);
  if (t == Vec2{}) t = normalized(p[i - 1] - p[i]);
  return t;
}

// One cubic for points[first..last] (more than two points) between unit tangents t1 and t2:
// the least-squares curve, re-parameterised by Newton–Raphson while it misses. `worst` gets the
// point to split at when it fails: the farthest point, or the middle when the points fit and
// the curve bows off the polyline between them.
bool fitOne(const std::vector<Vec2>& p, std::size_t first, std::size_t last, Vec2 t1, Vec2 t2, double tolerance,
            bool capHandles, CubicBezier& curve, std::size_t& worst) {
  const double tolerance2 = tolerance * tolerance;
  std::vector<double> u = chordLengthParameters(p, first, last);
  curve = leastSquaresCurve(p, first, last, u, t1, t2, capHandles);
  double error = maxSquaredError(p, first, last, curve, u, worst);
  // Newton–Raphson re-parameterisation [Sch90]. Schneider tries it only for near misses
  // (error below 4 tolerance²); chord-length parameters can be far off on unevenly
  // parameterised data, so it is tried whenever the fit fails, keeping the best curve.
  for (int k = 0; k < kReparameterisations && error >= tolerance2; ++k) {
    reparameterise(p, first, curve, u);
    const CubicBezier refit = leastSquaresCurve(p, first, last, u, t1, t2, capHandles);
    std::size_t refitWorst = 0;
    const double refitError = maxSquaredError(p, first, last, refit, u, refitWorst);
    if (refitError < error) {
      curve = refit;
      error = refitError;
      worst = refitWorst;
    }
  }
  if (error >= tolerance2) return false;
  if (!bowsOff(curve, p, first, last, tolerance)) return true;
  worst = (first + last) / 2;
  return false;
}

// The curve for a single edge: handles along the neighbours' tangents, unless they would bow
// the curve off the edge by more than the tolerance (a long edge between turns): then the edge.
CubicBezier edgeCurve(Vec2 a, Vec2 b, Vec2 t1, Vec2 t2, double tolerance) {
  const double third = distance(a, b) / 3.0;
  const CubicBezier curve{a, a + t1 * third, b + t2 * third, b};
  const bool bows = std::max(distanceToSegment(curve[1], a, b), distanceToSegment(curve[2], a, b)) > tolerance;
  return bows ? straight(a, b) : curve;
}

// Fits points[first..last] (distinct consecutive points) between unit tangents t1 (forwards at
// the first point) and t2 (backwards at the last), appending the curves to `out` in order.
// Schneider's way: split at the worst point until every piece fits.
void fitPieceSplitting(const std::vector<Vec2>& p, std::size_t first, std::size_t last, Vec2 t1, Vec2 t2,
                       double tolerance, std::vector<CubicBezier>& out) {
  struct Task { std::size_t first, last; Vec2 t1, t2; };
  std::vector<Task> stack{{first, last, t1, t2}};  // explicit stack: long noisy inputs split deeply
  while (!stack.empty()) {
    const Task task = stack.back();
    stack.pop_back();
    if (task.last - task.first == 1) {
      out.push_back(edgeCurve(p[task.first], p[task.last], task.t1, task.t2, tolerance));
      continue;
    }
    CubicBezier curve;
    std::size_t worst = 0;
    if (fitOne(p, task.first, task.last, task.t1, task.t2, tolerance, false, curve, worst)) {
      out.push_back(curve);
      continue;
    }
    const Vec2 centre = centreTangent(p, worst);
    stack.push_back({worst, task.last, -centre, task.t2});  // right half, done second
    stack.push_back({task.first, worst, task.t1, centre});
  }
}

// The same, each curve reaching as far along the points as one cubic can: from each start,
// a galloping then binary search for the farthest end that fits. Splitting at the worst point
// cuts where the error peaks, not where a curve must end, and leaves 2–3 times as many
// curves on smooth data.
void fitPieceLongest(const std::vector<Vec2>& p, std::size_t first, std::size_t last, Vec2 t1, Vec2 t2,
                     double tolerance, std::vector<CubicBezier>& out) {
  std::size_t start = first;
  Vec2 startTangent = t1;
  while (start < last) {
    auto tangentAt = [&](std::size_t end) { return end == last ? t2 : centreTangent(p, end); };
    CubicBezier best = edgeCurve(p[start], p[start + 1], startTangent, tangentAt(start + 1), tolerance);
    std::size_t bestEnd = start + 1;
    CubicBezier curve;
    std::size_t worst = 0;
    auto fits = [&](std::size_t end) {
      if (!fitOne(p, start, end, startTangent, tangentAt(end), tolerance, true, curve, worst)) return false;
      best = curve;
      bestEnd = end;
      return true;
    };
    if (last - start >= 2 && !fits(last)) {
      std::size_t failed = last;
      for (std::size_t span = 2; start + span < failed; span *= 2)
        if (!fits(start + span)) { failed = start + span; break; }
      std::size_t good = bestEnd;
      while (failed - good > 1) {
        const std::size_t middle = good + (failed - good) / 2;
        if (fits(middle)) good = middle; else failed = middle;
      }
      if (bestEnd != good) fits(good);
    }
    out.push_back(best);
    start = bestEnd;
    if (start < last) startTangent = -centreTangent(p, start);
  }
}

void fitPiece(const std::vector<Vec2>& p, std::size_t first, std::size_t last, Vec2 t1, Vec2 t2, double tolerance,
              FitSpans spans, std::vector<CubicBezier>& out) {
  if (spans == FitSpans::SplitAtWorst) fitPieceSplitting(p, first, last, t1, t2, tolerance, out);
  else fitPieceLongest(p, first, last, t1, t2, tolerance, out);
}

// Turn angle at vertex i between the incoming and outgoing segments, in [0, pi].
double turnAngle(Vec2 before, Vec2 at, Vec2 after) {
  const Vec2 a = at - before, b = after - at;
  return std::abs(std::atan2(cross(a, b), dot(a, b)));
}

}  // namespace

std::vector<CubicBezier> fitCubicBeziers(const Polyline& line, double tolerance, double cornerAngle, FitSpans spans) {
  checkInput(line, tolerance);
  const std::vector<Vec2> p = withoutDuplicates(line, false);
  if (p.empty()) return {};
  if (p.size() == 1) return {{p[0], p[0], p[0], p[0]}};
  if (p.size() == 2) return {straight(p[0], p[1])};
  std::vector<CubicBezier> out;
  std::size_t start = 0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    const bool end = i == p.size() - 1;
    if (!end && turnAngle(p[i - 1], p[i], p[i + 1]) <= cornerAngle) continue;
    fitPiece(p, start, i, normalized(p[start + 1] - p[start]), normalized(p[i - 1] - p[i]), tolerance, spans, out);
    start = i;
  }
  return out;
}

std::vector<CubicBezier> fitCubicBeziersClosed(const Ring& ring, double tolerance, double cornerAngle, FitSpans spans) {
  checkInput(ring, tolerance);
  std::vector<Vec2> p = withoutDuplicates(ring, true);
  if (p.empty()) return {};
  if (p.size() == 1) return {{p[0], p[0], p[0], p[0]}};
  if (p.size() == 2) return {straight(p[0], p[1]), straight(p[1], p[0])};
  const std::size_t n = p.size();
  std::vector<std::size_t> corners;
  for (std::size_t i = 0; i < n; ++i)
    if (turnAngle(p[(i + n - 1) % n], p[i], p[(i + 1) % n]) > cornerAngle) corners.push_back(i);
  p.push_back(p[0]);  // the chain returns to the first vertex
  std::vector<CubicBezier> out;
  // A smooth first vertex: both ends share the tangent through it.
  const bool smoothStart = corners.empty() || corners.front() != 0;
  const Vec2 startTangent = smoothStart ? normalized(p[1] - p[n - 1]) : normalized(p[1] - p[0]);
  const Vec2 endTangent = smoothStart ? -startTangent : normalized(p[n - 1] - p[n]);
  std::size_t start = 0;
  Vec2 t1 = startTangent == Vec2{} ? normalized(p[1] - p[0]) : startTangent;
  corners.push_back(n);
  for (std::size_t c : corners) {
    if (c == 0) continue;
    const Vec2 t2 = c == n ? (endTangent == Vec2{} ? normalized(p[n - 1] - p[n]) : endTangent)
                           : normalized(p[c - 1] - p[c]);
    fitPiece(p, start, c, t1, t2, tolerance, spans, out);
    start = c;
    if (c < n) t1 = normalized(p[c + 1] - p[c]);
  }
  return out;
}

Polyline flatten(const std::vector<CubicBezier>& curves, double tolerance) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw InputError("", "flattening tolerance must be a positive number");
  Polyline out;
  if (curves.empty()) return out;
  out.push_back(curves.front()[0]);
  auto emit = [&](Vec2 p) {
    if (!(p == out.back())) out.push_back(p);
  };
  // Adaptive de Casteljau halving: a curve lies in its control points' hull, so when both inner
  // points are within tolerance of the chord, the whole curve is.
  auto chordDistance = [](Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const double l2 = lengthSquared(ab);
    const double t = l2 > 0.0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return distance(p, a + ab * t);
  };
  constexpr int kMaxDepth = 24;
  struct Part { CubicBezier c; int depth; };
  for (const CubicBezier& curve : curves) {
    for (Vec2 q : curve)
      if (!std::isfinite(q.x) || !std::isfinite(q.y)) throw InputError("", "non-finite Bézier control point");
    std::vector<Part> stack{{curve, 0}};
    while (!stack.empty()) {
      const Part part = stack.back();
      stack.pop_back();
      const CubicBezier& c = part.c;
      if (part.depth >= kMaxDepth ||
          std::max(chordDistance(c[1], c[0], c[3]), chordDistance(c[2], c[0], c[3])) <= tolerance) {
        emit(c[3]);
        continue;
      }
      const Vec2 ab = (c[0] + c[1]) * 0.5, bc = (c[1] + c[2]) * 0.5, cd = (c[2] + c[3]) * 0.5;
      const Vec2 abc = (ab + bc) * 0.5, bcd = (bc + cd) * 0.5, mid = (abc + bcd) * 0.5;
      stack.push_back({{mid, bcd, cd, c[3]}, part.depth + 1});
      stack.push_back({{c[0], ab, abc, mid}, part.depth + 1});
    }
  }
  return out;
}

double fitDeviation(const std::vector<Vec2>& points, bool closed, const std::vector<CubicBezier>& curves, double precision) {
  double largest = largestDistanceToChain(points, curves, precision);
  std::vector<Vec2> polygon = points;
  if (closed && !points.empty()) polygon.push_back(points.front());
  if (polygon.size() < 2) return largest;
  std::vector<CubicBezier> edges;  // the polygon as a chain of straight curves
  for (std::size_t k = 1; k < polygon.size(); ++k) edges.push_back(straight(polygon[k - 1], polygon[k]));
  // The chain sampled every 5 precisions (a straight piece flattens to its ends alone), so
  // this half is measured within 2.5 precisions.
  return std::max(largest, largestDistanceToChain(resamplePolyline(flatten(curves, precision), 5.0 * precision), edges,
                                                  precision));
}

double largestDistanceToChain(const std::vector<Vec2>& points, const std::vector<CubicBezier>& curves, double precision) {
  const Polyline chain = flatten(curves, precision);
  const std::size_t n = chain.size();
  double largest2 = 0.0;
  // Consecutive points are usually near the same part of the chain: the segments around the
  // last one's nearest give a bound first, and the full scan stops as soon as the point is
  // no further than the largest distance so far.
  constexpr std::size_t kWindow = 8;
  std::size_t near = 1;
  for (Vec2 p : points) {
    auto squared = [&](std::size_t k) { return lengthSquared(p - closestPointOnSegment(p, chain[k - 1], chain[k])); };
    double best2 = lengthSquared(p - chain.front());
    std::size_t nearest = near;
    auto consider = [&](std::size_t k) {
      const double d2 = squared(k);
      if (d2 < best2) best2 = d2, nearest = k;
    };
    for (std::size_t k = near > kWindow ? near - kWindow : 1; k < n && k <= near + kWindow; ++k) consider(k);
    for (std::size_t k = 1; k < n && best2 > largest2; ++k) consider(k);
    near = nearest;
    largest2 = std::max(largest2, best2);
  }
  return std::sqrt(largest2);
}

}  // namespace pak
