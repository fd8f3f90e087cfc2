// Probes (scene key probes): named points sampled at every record by the MLS interpolant itself,
// u^h(x) = sum_I phi_I(x) d_I and grad u^h(x) = sum_I d_I (grad phi_I(x))^T (the shape functions
// at the point, not the nearest particle's values). Columns per probe, in the history file and
// the Exodus globals: probe_<name>_u<axis>, the small-strain tensor probe_<name>_e<ij> and, for
// parts of elastic (path-independent) materials, the stress of the part's law at the point
// probe_<name>_s<ij> (Cauchy for small strain, first Piola-Kirchhoff for total_lagrangian).
// Components ij: xx, yy, xy in 2D; xx, yy, zz, yz, xz, xy in 3D.
#pragma once

#include <string>
#include <vector>

#include "operators/MixedPressure.hpp"
#include "operators/SolidOperator.hpp"

namespace efg {

/// The column names of the scene's probes, in record order.
std::vector<std::string> probe_names(const Scene& scene, int dimension);

/// Values in probe_names order (collective: the rank owning the particle nearest to a probe
/// evaluates it, every rank gets the result). `d_overlap`: generalized displacements.
/// Mixed u-p parts (`mixed`): the stress is the law's deviatoric part at the point minus the
/// pressure interpolated from the particles' (the means of their cells').
std::vector<double> probe_values(const Model& model, const SolidOperator& op,
                                 const Vector& d_overlap, const MixedPressure* mixed = nullptr);

}  // namespace efg
