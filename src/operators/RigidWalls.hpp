// Fixed planar rigid walls (LS-DYNA *RIGIDWALL_PLANAR) on the particles' physical positions
// x_J = X_J + sum_I phi_I(X_J) d_I: a particle behind the plane (gap g < 0 along the unit normal)
// gets the penalty force F = -k g n, k = penalty x M_J / dt^2 (stable for penalty <= 1), spread
// to the generalized dofs as f_I += phi_I(X_J) F (work-consistent with the shape functions).
#pragma once

#include <string>
#include <vector>

#include "operators/ModelOperators.hpp"

namespace efg {

class RigidWalls {
 public:
  RigidWalls(const ModelOperators& ops, const Vector& mass_owned);

  bool empty() const { return walls_.empty(); }
  std::size_t count() const { return walls_.size(); }
  const std::string& name(std::size_t w) const { return walls_[w].name; }

  /// Adds the wall forces at displacement d to f (overlap) and returns the normal force on each
  /// wall (summed over ranks).
  std::vector<double> add_forces(const Vector& d_overlap, double dt, Vector& f_overlap) const;

 private:
  struct Contact {
    std::array<double, 3> X{};
    double mass;
    std::vector<int> nodes;
    std::vector<double> phi;
  };
  struct Wall {
    std::string name;
    std::array<double, 3> point{}, normal{};
    double penalty;
    std::vector<Contact> particles;
  };
  int dim_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::vector<Wall> walls_;
};

}  // namespace efg
