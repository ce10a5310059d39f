#include "script/curves.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace taa::script {

namespace {

using spec::CurveType;
using Points = std::vector<glm::dvec3>;

Points toDouble(const std::vector<glm::vec3>& points) {
  Points out;
  out.reserve(points.size());
  for (const auto& p : points) out.emplace_back(p);
  return out;
}

// One Bezier curve of degree n-1; the last de Casteljau level also gives the
// derivative, so no separate hodograph is needed.
CurvePoint bezier(Points pts, double u) {
  const size_t degree = pts.size() - 1;
  for (size_t level = degree; level > 1; --level)
    for (size_t i = 0; i < level; ++i) pts[i] = glm::mix(pts[i], pts[i + 1], u);
  return {glm::mix(pts[0], pts[1], u), static_cast<double>(degree) * (pts[1] - pts[0])};
}

// de Boor's algorithm; knots.size() == ctrl.size() + degree + 1 and x lies in
// [knots[degree], knots[ctrl.size()]].
glm::dvec3 deBoor(int degree, const std::vector<double>& knots, const Points& ctrl, double x) {
  const int last = static_cast<int>(ctrl.size()) - 1;
  int k = degree;
  while (k < last && x >= knots[k + 1]) ++k;
  Points d(ctrl.begin() + (k - degree), ctrl.begin() + (k + 1));
  for (int r = 1; r <= degree; ++r)
    for (int j = degree; j >= r; --j) {
      const double lo = knots[j + k - degree];
      const double span = knots[j + 1 + k - r] - lo;
      const double alpha = span > 0.0 ? (x - lo) / span : 0.0;
      d[j] = glm::mix(d[j - 1], d[j], alpha);
    }
  return d[degree];
}

// Uniform B-spline: clamped (open-uniform knots, interpolates the end points) or
// periodic (control points wrapped, closed and C^(degree-1) everywhere).
CurvePoint bspline(const Points& pts, int wantedDegree, bool cyclic, double u) {
  const int n = static_cast<int>(pts.size());
  Points ctrl;
  std::vector<double> knots;
  int degree = wantedDegree;
  double x0 = 0.0, extent = 0.0;
  if (cyclic) {
    for (int i = 0; i < n + degree; ++i) ctrl.push_back(pts[i % n]);
    for (int i = 0; i <= n + 2 * degree; ++i) knots.push_back(i);
    x0 = degree;
    extent = n;
  } else {
    degree = std::min(wantedDegree, n - 1);  // too few points: the highest degree they allow
    ctrl = pts;
    for (int i = 0; i <= n + degree; ++i) knots.push_back(std::clamp(i - degree, 0, n - degree));
    extent = n - degree;
  }
  const double x = x0 + u * extent;
  CurvePoint out;
  out.position = deBoor(degree, knots, ctrl, x);
  // The derivative is a B-spline of one degree less on the inner knots.
  Points dctrl;
  for (size_t i = 0; i + 1 < ctrl.size(); ++i) {
    const double span = knots[i + degree + 1] - knots[i + 1];
    dctrl.push_back(span > 0.0 ? double(degree) * (ctrl[i + 1] - ctrl[i]) / span : glm::dvec3(0.0));
  }
  const std::vector<double> dknots(knots.begin() + 1, knots.end() - 1);
  out.tangent = deBoor(degree - 1, dknots, dctrl, x) * extent;
  return out;
}

// Uniform Catmull-Rom through every point; open ends duplicate the end points.
CurvePoint catmullRom(const Points& pts, bool cyclic, double u) {
  const int n = static_cast<int>(pts.size());
  const int segments = cyclic ? n : n - 1;
  const double x = u * segments;
  const int i = std::clamp(static_cast<int>(std::floor(x)), 0, segments - 1);
  const double t = x - i;
  auto at = [&](int j) { return cyclic ? pts[((j % n) + n) % n] : pts[std::clamp(j, 0, n - 1)]; };
  const glm::dvec3 p0 = at(i - 1), p1 = at(i), p2 = at(i + 1), p3 = at(i + 2);
  const glm::dvec3 a = 2.0 * p1, b = p2 - p0, c = 2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3;
  const glm::dvec3 d = -p0 + 3.0 * p1 - 3.0 * p2 + p3;
  return {0.5 * (a + t * (b + t * (c + t * d))),
          0.5 * (b + t * (2.0 * c + t * 3.0 * d)) * double(segments)};
}

}  // namespace

CurvePoint evaluateCurve(const spec::PathSpec& path, double u) {
  u = std::clamp(u, 0.0, 1.0);
  Points pts = toDouble(path.points);
  if (pts.empty()) return {};
  if (pts.size() == 1) return {pts[0], glm::dvec3(0.0)};
  switch (path.type) {
    case CurveType::Bezier:
      if (path.cyclic) pts.push_back(pts.front());
      return bezier(std::move(pts), u);
    case CurveType::BSpline2:
      return bspline(pts, 2, path.cyclic, u);
    case CurveType::BSpline3:
      return bspline(pts, 3, path.cyclic, u);
    case CurveType::CatmullRom:
      return catmullRom(pts, path.cyclic, u);
  }
  return {};
}

double pathTimeFraction(const spec::PathSpec& path, double timeSeconds) {
  if (!(path.duration_s > 0.0f)) return path.cyclic ? 0.0 : 1.0;
  const double f = timeSeconds / static_cast<double>(path.duration_s);
  if (path.cyclic) return f - std::floor(f);
  return std::clamp(f, 0.0, 1.0);
}

Path::Path(const spec::PathSpec& spec) : spec_(spec) {
  if (spec_.points.empty()) return;
  cumulative_.resize(kArcLengthSamples + 1, 0.0);
  glm::dvec3 prev = evaluateCurve(spec_, 0.0).position;
  for (int i = 1; i <= kArcLengthSamples; ++i) {
    const glm::dvec3 p = evaluateCurve(spec_, double(i) / kArcLengthSamples).position;
    cumulative_[i] = cumulative_[i - 1] + glm::length(p - prev);
    prev = p;
  }
}

double Path::parameterAtArcFraction(double fraction) const {
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (!(length() > 0.0)) return fraction;  // a point-like path: any parameter is as good
  const double s = fraction * length();
  // First sample whose cumulative length exceeds s; the chord before it holds s.
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  if (it == cumulative_.end()) return 1.0;
  const int hi = static_cast<int>(it - cumulative_.begin());
  const double c0 = cumulative_[hi - 1], c1 = cumulative_[hi];
  const double w = c1 > c0 ? (s - c0) / (c1 - c0) : 0.0;
  return (hi - 1 + w) / kArcLengthSamples;
}

double Path::parameterAtTime(double timeSeconds) const {
  const double f = pathTimeFraction(spec_, timeSeconds);
  return spec_.constant_speed ? parameterAtArcFraction(f) : f;
}

CurvePoint Path::atTime(double timeSeconds) const {
  return evaluateCurve(spec_, parameterAtTime(timeSeconds));
}

}  // namespace taa::script
