// Analytic rigid shapes and the signed distance of a point to them (plain functions, no
// Trilinos): the gap g (< 0 inside the body) and the outward unit normal at the closest surface
// point. A body translated by u is the shape evaluated at x - u.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>

#include "contact/RigidOrientation.hpp"

namespace efg::contact {

class MeshSurface;  // contact/MeshSurface.hpp

struct Shape {
  enum class Kind { plane, sphere, cylinder, box, mesh };
  Kind kind = Kind::plane;
  int dim = 3;
  double point[3] = {0, 0, 0}, normal[3] = {0, 0, 1};  ///< plane, unit normal out of the body
  double center[3] = {0, 0, 0}, axis[3] = {0, 0, 1};   ///< sphere, cylinder (unit axis, 3D)
  double radius = 0;
  double lower[3] = {0, 0, 0}, upper[3] = {0, 0, 0};  ///< axis-aligned box
  std::shared_ptr<const MeshSurface> mesh;            ///< mesh blocks (centroid in `center`)
};

/// The point a body's moments are taken about (moved with the body): a plane's point, the centre
/// of a sphere or cylinder, the centre of a box, the centroid of a mesh body's cells.
inline void reference_point(const Shape& s, double (&c)[3]) {
  for (int k = 0; k < 3; ++k)
    c[k] = s.kind == Shape::Kind::plane ? s.point[k]
           : s.kind == Shape::Kind::box ? 0.5 * (s.lower[k] + s.upper[k])
                                        : s.center[k];
}

/// M += (x - (reference point + u_body)) x F: the moment of a force F on the body applied at x
/// (2D: only M[2] is nonzero).
inline void add_moment(const Shape& s, const double* u_body, const double* x, const double* F,
                       double* M) {
  double c[3], r[3] = {0, 0, 0};
  reference_point(s, c);
  for (int k = 0; k < s.dim; ++k) r[k] = x[k] - (c[k] + u_body[k]);
  M[0] += r[1] * F[2] - r[2] * F[1];
  M[1] += r[2] * F[0] - r[0] * F[2];
  M[2] += r[0] * F[1] - r[1] * F[0];
}

struct Proximity {
  double gap = 0;                ///< signed distance, negative inside
  double normal[3] = {0, 0, 0};  ///< outward unit normal of the surface nearest x
};

/// Proximity of y (the body's frame) to a mesh body's surface (contact/MeshSurface.cpp).
Proximity mesh_proximity(const MeshSurface& mesh, const double* y);

namespace detail {
// Distance from center along the part of x - c normal to the axis (all of it for a sphere or
// a 2D cylinder, which is a disc).
inline Proximity round(const Shape& s, const double* x, bool along_axis_removed) {
  double r[3] = {0, 0, 0};
  for (int k = 0; k < s.dim; ++k) r[k] = x[k] - s.center[k];
  if (along_axis_removed) {
    double t = 0;
    for (int k = 0; k < 3; ++k) t += r[k] * s.axis[k];
    for (int k = 0; k < 3; ++k) r[k] -= t * s.axis[k];
  }
  const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  Proximity p;
  p.gap = len - s.radius;
  if (len > 0)
    for (int k = 0; k < 3; ++k) p.normal[k] = r[k] / len;
  else
    p.normal[s.dim - 1] = 1.0;  // the center itself: any direction is nearest
  return p;
}

inline Proximity box(const Shape& s, const double* x) {
  Proximity p;
  bool inside = true;
  double outside2 = 0, d[3] = {0, 0, 0};
  for (int k = 0; k < s.dim; ++k) {
    if (x[k] < s.lower[k]) d[k] = x[k] - s.lower[k];
    if (x[k] > s.upper[k]) d[k] = x[k] - s.upper[k];
    if (d[k] != 0) inside = false;
    outside2 += d[k] * d[k];
  }
  if (!inside) {
    p.gap = std::sqrt(outside2);
    for (int k = 0; k < s.dim; ++k) p.normal[k] = d[k] / p.gap;
    return p;
  }
  // Inside: the nearest face decides.
  p.gap = -1e300;
  for (int k = 0; k < s.dim; ++k) {
    const double to_lower = x[k] - s.lower[k], to_upper = s.upper[k] - x[k];
    if (-to_lower > p.gap) {
      p.gap = -to_lower;
      for (int j = 0; j < 3; ++j) p.normal[j] = j == k ? -1.0 : 0.0;
    }
    if (-to_upper > p.gap) {
      p.gap = -to_upper;
      for (int j = 0; j < 3; ++j) p.normal[j] = j == k ? 1.0 : 0.0;
    }
  }
  return p;
}
}  // namespace detail

/// Gap and normal of point x to the shape translated by u.
inline Proximity proximity(const Shape& s, const double* x, const double* u);

/// Gap and normal of point x to the shape translated by u and turned by `angle` about its
/// reference point (2D, counterclockwise): the point is taken into the body's frame,
/// y = c + R(-angle) (x - u - c), and the normal back out, n = R(angle) n_body. A turn leaves
/// planes, discs and spheres as they are; rotating 2D boxes and mesh bodies need it.
inline Proximity proximity_turned(const Shape& s, const double* x, const double* u, double angle) {
  if (angle == 0.0 || s.dim != 2 || (s.kind != Shape::Kind::box && s.kind != Shape::Kind::mesh))
    return proximity(s, x, u);
  double c[3];
  reference_point(s, c);
  const double co = std::cos(angle), si = std::sin(angle);
  const double r[2] = {x[0] - u[0] - c[0], x[1] - u[1] - c[1]};
  const double body[3] = {c[0] + co * r[0] + si * r[1], c[1] - si * r[0] + co * r[1], 0.0};
  const double none[3] = {0, 0, 0};
  auto p = proximity(s, body, none);
  const double n[2] = {p.normal[0], p.normal[1]};
  p.normal[0] = co * n[0] - si * n[1];
  p.normal[1] = si * n[0] + co * n[1];
  return p;
}

/// Gap and normal of point x to the shape translated by u and turned by R about its reference
/// point (3D boxes, cylinders and mesh bodies; spheres and planes are taken as they are): the point is taken
/// into the body's frame, y = c + R^T (x - u - c), and the normal back out, n = R n_body.
inline Proximity proximity_oriented(const Shape& s, const double* x, const double* u,
                                    const Orientation& R) {
  if (s.dim != 3 ||
      (s.kind != Shape::Kind::box && s.kind != Shape::Kind::cylinder &&
       s.kind != Shape::Kind::mesh) ||
      R == identity_orientation())
    return proximity(s, x, u);
  double c[3], r[3], b[3];
  reference_point(s, c);
  for (int k = 0; k < 3; ++k) r[k] = x[k] - u[k] - c[k];
  to_body(R, r, b);
  const double body[3] = {c[0] + b[0], c[1] + b[1], c[2] + b[2]}, none[3] = {0, 0, 0};
  auto p = proximity(s, body, none);
  const double n[3] = {p.normal[0], p.normal[1], p.normal[2]};
  to_world(R, n, p.normal);
  return p;
}

/// The body's proximity at its state: 2D boxes turned by the angle about z, 3D boxes and
/// cylinders by their orientation.
inline Proximity proximity_of_body(const Shape& s, const double* x, const double* u, double angle_z,
                                   const Orientation& R) {
  return s.dim == 2 ? proximity_turned(s, x, u, angle_z) : proximity_oriented(s, x, u, R);
}

inline Proximity proximity(const Shape& s, const double* x, const double* u) {
  double y[3] = {0, 0, 0};
  for (int k = 0; k < s.dim; ++k) y[k] = x[k] - u[k];
  switch (s.kind) {
    case Shape::Kind::plane: {
      Proximity p;
      for (int k = 0; k < s.dim; ++k) {
        p.gap += (y[k] - s.point[k]) * s.normal[k];
        p.normal[k] = s.normal[k];
      }
      return p;
    }
    case Shape::Kind::sphere:
      return detail::round(s, y, false);
    case Shape::Kind::cylinder:
      return detail::round(s, y, s.dim == 3);
    case Shape::Kind::box:
      return detail::box(s, y);
    case Shape::Kind::mesh:
      return mesh_proximity(*s.mesh, y);
  }
  return {};
}

/// dn/dx at a point with proximity p to shape s (translated bodies alike): (I - n n^T) / rho for
/// a sphere or a 2D cylinder (a disc), rho the distance from the center; (I - n n^T - a a^T) /
/// rho for a 3D cylinder of axis a; 0 for planes and box faces. The curvature term of the
/// penalty contact's tangent.
inline void normal_derivative(const Shape& s, const Proximity& p, double (&dn)[3][3]) {
  for (auto& row : dn)
    for (double& v : row) v = 0.0;
  const bool disc_or_ball =
      s.kind == Shape::Kind::sphere || (s.kind == Shape::Kind::cylinder && s.dim == 2);
  if (!disc_or_ball && s.kind != Shape::Kind::cylinder) return;
  const double rho = s.radius + p.gap;  // distance from the center or axis
  if (!(rho > 0)) return;
  const bool axial = !disc_or_ball;
  for (int i = 0; i < s.dim; ++i)
    for (int j = 0; j < s.dim; ++j)
      dn[i][j] = ((i == j ? 1.0 : 0.0) - p.normal[i] * p.normal[j] -
                  (axial ? s.axis[i] * s.axis[j] : 0.0)) /
                 rho;
}

}  // namespace efg::contact
