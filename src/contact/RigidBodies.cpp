#include "contact/RigidBodies.hpp"

#include <cmath>
#include <sstream>

#include "contact/MeshSurface.hpp"
#include "core/Errors.hpp"
#include "model/Curves.hpp"
#include "scene/ContactInput.hpp"

namespace efg {
namespace {

void unit(const std::vector<double>& v, double* out, int dim) {
  double n2 = 0;
  for (int k = 0; k < dim; ++k)
    n2 += v[static_cast<std::size_t>(k)] * v[static_cast<std::size_t>(k)];
  for (int k = 0; k < dim; ++k) out[k] = v[static_cast<std::size_t>(k)] / std::sqrt(n2);
}

contact::Shape shape_of(const RigidBodySpec& b, int dim) {
  using Kind = contact::Shape::Kind;
  contact::Shape s;
  s.dim = dim;
  const auto copy = [dim](const std::vector<double>& v, double* out) {
    for (int k = 0; k < dim && static_cast<std::size_t>(k) < v.size(); ++k)
      out[k] = v[static_cast<std::size_t>(k)];
  };
  if (b.shape == "plane") {
    s.kind = Kind::plane;
    copy(b.point, s.point);
    unit(b.normal, s.normal, dim);
  } else if (b.shape == "sphere" || b.shape == "cylinder") {
    s.kind = b.shape == "sphere" ? Kind::sphere : Kind::cylinder;
    copy(b.center, s.center);
    s.radius = b.radius;
    if (dim == 3 && !b.axis.empty()) unit(b.axis, s.axis, 3);
  } else if (b.shape == "mesh") {
    s.kind = Kind::mesh;
    s.mesh = std::make_shared<const contact::MeshSurface>(b.surface);
    for (int k = 0; k < 3; ++k) s.center[k] = b.surface->centroid[static_cast<std::size_t>(k)];
  } else {
    s.kind = Kind::box;
    copy(b.lower, s.lower);
    copy(b.upper, s.upper);
  }
  return s;
}

// The inertia tensor about the centre for the rotation of free bodies (body axes, row major):
// a disc m R^2 / 2 (about z), a sphere 2 m R^2 / 5, a 2D box m (w^2 + h^2) / 12 (about z; a
// rectangle of sides w, h), a 3D box m / 12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2) of sides
// a, b, c; mesh cells (uniform density m / V) rho (tr(S) I - S) from the cells' second moments S
// about their centroid (mesh/RigidSurface), 2D rho t (S_xx + S_yy) about z.
std::array<double, 9> rigid_body_inertia(const RigidBodySpec& b, int dim) {
  const double m = rigid_body_mass(b, dim);
  const auto diagonal = [](double a, double c, double d) {
    return std::array<double, 9>{a, 0, 0, 0, c, 0, 0, 0, d};
  };
  if (b.shape == "mesh") {
    const auto& S = b.surface->second_moment;  // xx, yy, zz, xy, xz, yz per unit density
    const double rho =
        b.surface->volume > 0 ? m / (b.surface->volume * (dim == 2 ? b.thickness : 1.0)) : 0.0;
    if (dim == 2) {
      const double I = rho * b.thickness * (S[0] + S[1]);
      return diagonal(I, I, I);
    }
    const double trace = S[0] + S[1] + S[2];
    return {rho * (trace - S[0]), -rho * S[3],          -rho * S[4],
            -rho * S[3],          rho * (trace - S[1]), -rho * S[5],
            -rho * S[4],          -rho * S[5],          rho * (trace - S[2])};
  }
  if (b.shape == "box") {
    double side[3] = {0, 0, 0};
    for (std::size_t k = 0; k < static_cast<std::size_t>(dim); ++k)
      side[k] = b.upper[k] - b.lower[k];
    const auto sq = [](double v) { return v * v; };
    return diagonal(m * (sq(side[1]) + sq(side[2])) / 12.0, m * (sq(side[0]) + sq(side[2])) / 12.0,
                    m * (sq(side[0]) + sq(side[1])) / 12.0);
  }
  const double I = m * b.radius * b.radius * (b.shape == "sphere" ? 0.4 : 0.5);
  return diagonal(I, I, I);
}

}  // namespace

RigidBodies::RigidBodies(const Scene& scene, int dim) : scene_(scene), dim_(dim) {
  for (const auto& b : scene.rigid_bodies) {
    std::array<std::string, 3> axis_curve = {b.curve, b.curve, b.curve};
    for (std::size_t k = 0; k < b.axis_curves.size(); ++k) axis_curve[k] = b.axis_curves[k];
    bodies_.push_back({b.name, b.motion, b.curve, axis_curve, b.velocity, b.gravity,
                       shape_of(b, dim), rigid_body_mass(b, dim), b.force, b.angular_velocity,
                       rigid_body_inertia(b, dim)});
  }
  scene_count_ = bodies_.size();
  for (const auto& w : scene.rigid_walls) {
    RigidBodySpec plane;
    plane.shape = "plane";
    plane.point = w.point;
    plane.normal = w.normal;
    bodies_.push_back(
        {"wall " + w.name, "fixed", "", {}, {}, {}, shape_of(plane, dim), 0.0, {}, {}, {}});
  }
}

std::vector<RigidBodyState> RigidBodies::initial_states(double time) const {
  std::vector<RigidBodyState> states(bodies_.size());
  const auto factor = curve_factor(scene_, time, 1.0);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const auto& spec = bodies_[b];
    for (std::size_t k = 0; k < spec.velocity.size(); ++k)
      states[b].velocity[k] =
          spec.velocity[k] * (spec.motion == "prescribed" ? factor(spec.axis_curve[k]) : 1.0);
    const auto& w = spec.angular_velocity;  // 2D: about z; prescribed: x curve
    const double spin = spec.motion == "prescribed" ? factor(spec.curve) : 1.0;
    for (std::size_t k = 0; k < w.size(); ++k)
      states[b].angular_velocity[w.size() == 1 ? 2 : k] = w[k] * spin;
    auto& s = states[b];
    contact::inertia_times(s.orientation, spec.inertia.data(), s.angular_velocity.data(),
                           s.angular_momentum.data());
  }
  return states;
}

void RigidBodies::move(std::vector<RigidBodyState>& states, double time, double dt) const {
  const auto mid = curve_factor(scene_, time + 0.5 * dt, 1.0);
  const auto end = curve_factor(scene_, time + dt, 1.0);
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const auto& spec = bodies_[b];
    auto& s = states[b];
    if (spec.motion == "free") {
      for (int k = 0; k < dim_; ++k) {
        s.velocity[k] += 0.5 * dt * acceleration(b, k, s, time);
        s.displacement[k] += dt * s.velocity[k];
      }
      if (rotates(b)) turn_free(b, s, dt);
    } else if (spec.motion == "prescribed") {
      for (std::size_t k = 0; k < spec.velocity.size(); ++k) {
        s.displacement[k] += dt * spec.velocity[k] * mid(spec.axis_curve[k]);
        s.velocity[k] = spec.velocity[k] * end(spec.axis_curve[k]);
      }
      // A prescribed spin (angular_velocity x curve), turned at mid-step like the translation.
      const auto& w = spec.angular_velocity;
      double turn[3] = {0, 0, 0};
      for (std::size_t k = 0; k < w.size(); ++k) {
        const std::size_t axis = w.size() == 1 ? 2 : k;
        turn[axis] = dt * w[k] * mid(spec.curve);
        s.rotation[axis] += turn[axis];
        s.angular_velocity[axis] = w[k] * end(spec.curve);
      }
      if (dim_ == 3) s.orientation = contact::turned(s.orientation, turn);
    }
  }
}

void RigidBodies::finish(std::vector<RigidBodyState>& states, double time_end, double dt) const {
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (bodies_[b].motion == "free") {
      for (int k = 0; k < dim_; ++k)
        states[b].velocity[k] += 0.5 * dt * acceleration(b, k, states[b], time_end);
      if (rotates(b)) {  // L^(n+1) = L^(n+1/2) + dt/2 M, omega^(n+1) = I(R^(n+1))^-1 L
        auto& s = states[b];
        for (std::size_t k = 0; k < 3; ++k) s.angular_momentum[k] += 0.5 * dt * s.moment[k];
        contact::inertia_times(s.orientation, bodies_[b].inertia.data(), s.angular_momentum.data(),
                               s.angular_velocity.data(), true);
      }
    }
}

void RigidBodies::turn_free(std::size_t b, RigidBodyState& s, double dt) const {
  // L^(n+1/2) = L^n + dt/2 M^n; the turn over the step at the mid-step's angular velocity,
  // omega^(n+1/2) = I(R^(n+1/2))^-1 L^(n+1/2) with R^(n+1/2) predicted by half a step at omega^n
  // (second order; a torque-free body keeps L exactly); R^(n+1) = exp(dt omega^(n+1/2)) R^n. In
  // 2D the body turns about z alone and this is omega += dt/2 M / I, angle += dt omega.
  const double* I = bodies_[b].inertia.data();
  for (std::size_t k = 0; k < 3; ++k) s.angular_momentum[k] += 0.5 * dt * s.moment[k];
  double half[3], w[3];
  for (std::size_t k = 0; k < 3; ++k) half[k] = 0.5 * dt * s.angular_velocity[k];
  const auto mid = dim_ == 3 ? contact::turned(s.orientation, half) : s.orientation;
  contact::inertia_times(mid, I, s.angular_momentum.data(), w, true);
  double turn[3];
  for (std::size_t k = 0; k < 3; ++k) {
    s.angular_velocity[k] = w[k];
    turn[k] = dt * w[k];
    s.rotation[k] += turn[k];
  }
  if (dim_ == 3) s.orientation = contact::turned(s.orientation, turn);
}

double RigidBodies::applied_force(std::size_t b, int k, double time, double no_curve) const {
  const auto& f = bodies_[b].force;
  if (static_cast<std::size_t>(k) >= f.size()) return 0.0;
  return f[static_cast<std::size_t>(k)] * curve_factor(scene_, time, no_curve)(bodies_[b].curve);
}

std::array<double, 3> RigidBodies::static_load(std::size_t b, double time, double no_curve) const {
  std::array<double, 3> load{};
  for (int k = 0; k < dim_; ++k)
    load[static_cast<std::size_t>(k)] =
        applied_force(b, k, time, no_curve) + no_curve * bodies_[b].mass * gravity(b, k);
  return load;
}

std::array<double, 3> RigidBodies::static_load_axis(std::size_t b) const {
  const auto unit_of = [this](const std::vector<double>& v) {
    std::array<double, 3> axis{};
    double size = 0;
    for (std::size_t k = 0; k < v.size() && k < static_cast<std::size_t>(dim_); ++k) {
      axis[k] = v[k];
      size += v[k] * v[k];
    }
    for (auto& a : axis) a = size > 0 ? a / std::sqrt(size) : 0.0;
    return axis;
  };
  const auto axis = unit_of(bodies_[b].force);
  return axis[0] != 0 || axis[1] != 0 || axis[2] != 0 ? axis : unit_of(bodies_[b].gravity);
}

std::array<double, 3> RigidBodies::prescribed_travel(std::size_t b, double t0, double t1) const {
  std::array<double, 3> u{};
  const auto& body = bodies_[b];
  if (body.motion != "prescribed") return u;
  for (std::size_t k = 0; k < body.velocity.size(); ++k) {
    const auto& name = body.axis_curve[k];
    const CurveSpec* c = name.empty() ? nullptr : scene_.find_curve(name);
    u[k] = body.velocity[k] * (c ? curve_integral(*c, t0, t1) : t1 - t0);
  }
  return u;
}

std::array<double, 3> RigidBodies::prescribed_turn(std::size_t b, double t0, double t1) const {
  std::array<double, 3> turn{};
  const auto& body = bodies_[b];
  if (body.motion != "prescribed" || body.angular_velocity.empty()) return turn;
  const CurveSpec* c = body.curve.empty() ? nullptr : scene_.find_curve(body.curve);
  const double integral = c ? curve_integral(*c, t0, t1) : t1 - t0;
  const auto& w = body.angular_velocity;
  for (std::size_t k = 0; k < w.size(); ++k) turn[w.size() == 1 ? 2 : k] = w[k] * integral;
  return turn;
}

double RigidBodies::applied_work(const std::vector<RigidBodyState>& before,
                                 const std::vector<RigidBodyState>& after, double t0,
                                 double t1) const {
  double work = 0;
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (is_free(b))
      for (int k = 0; k < dim_; ++k)
        work += (bodies_[b].mass * gravity(b, k) +
                 0.5 * (applied_force(b, k, t0) + applied_force(b, k, t1))) *
                (after[b].displacement[k] - before[b].displacement[k]);
  return work;
}

double RigidBodies::kinetic_energy(const std::vector<RigidBodyState>& states) const {
  double e = 0;
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (is_free(b)) {
      for (int k = 0; k < dim_; ++k)
        e += 0.5 * bodies_[b].mass * states[b].velocity[k] * states[b].velocity[k];
      for (std::size_t k = 0; k < 3; ++k)  // omega . L / 2
        e += 0.5 * states[b].angular_velocity[k] * states[b].angular_momentum[k];
    }
  return e;
}

void RigidBodies::check_contact_mass(std::size_t b, double penalty_mass, const char* where) const {
  if (!is_free(b) || penalty_mass <= mass(b)) return;
  std::ostringstream o;
  o << "rigid body '" << name(b) << "' (mass " << mass(b) << ") is too light for its contact"
    << where << ": penalty x the mass of the particles it touches is " << penalty_mass
    << "; its contact would be unstable at this time step (give it more mass or lower the "
       "contact's penalty)";
  throw NumericalError(o.str());
}

std::array<double, 3> RigidBodies::momentum(const std::vector<RigidBodyState>& states) const {
  std::array<double, 3> p{};
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (is_free(b))
      for (int k = 0; k < dim_; ++k) p[k] += bodies_[b].mass * states[b].velocity[k];
  return p;
}

}  // namespace efg
