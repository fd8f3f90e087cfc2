#include "model/MaterialLaws.hpp"

#include <stdexcept>

#include "materials/ElasticConstants.hpp"

namespace efg {

physics::SolidMaterial solid_material(const MaterialSpec& material, const PartSpec& part,
                                      int dimension) {
  const double e = material.constants.at("youngs_modulus"),
               nu = material.constants.at("poissons_ratio");
  const bool plane_stress = dimension == 2 && part.plane_stress;
  const auto c =
      plane_stress ? physics::plane_stress_constants(e, nu) : physics::elastic_constants(e, nu);
  physics::SolidMaterial m;
  m.kind = material.model == "neo_hookean" ? physics::MaterialKind::neo_hookean
                                           : physics::MaterialKind::linear_elastic;
  m.lambda = c.lambda;
  m.mu = c.mu;
  m.plane_stress = plane_stress;
  return m;
}

namespace {

// The scene reader has checked the curve (exists, starts at (0, yield_stress), at most
// max_curve_points further points, strain increasing, stress not decreasing).
physics::J2Parameters j2_parameters(const Scene& scene, const MaterialSpec& material,
                                    const PartSpec& part, int dimension) {
  const auto& k = material.constants;
  // The law takes the 3D constants; plane stress is solved inside it (sigma_33 = 0).
  const auto c = physics::elastic_constants(k.at("youngs_modulus"), k.at("poissons_ratio"));
  const double yield = k.at("yield_stress");
  const auto hardening = k.find("hardening_modulus");
  physics::J2Parameters p = physics::j2_linear_hardening(
      c.lambda, c.mu, yield, hardening == k.end() ? 0.0 : hardening->second);
  if (!material.hardening_curve.empty()) {
    const CurveSpec* curve = scene.find_curve(material.hardening_curve);
    if (!curve) throw std::logic_error("unchecked hardening curve " + material.hardening_curve);
    p.curve_points = 0;
    for (std::size_t i = 1; i < curve->time.size(); ++i) {
      p.curve_strain[p.curve_points] = curve->time[i];
      p.curve_stress[p.curve_points] = curve->value[i];
      ++p.curve_points;
    }
  }
  if (k.count("rate_c")) p.rate_c = k.at("rate_c");
  if (k.count("rate_p")) p.rate_p = k.at("rate_p");
  if (k.count("failure_strain")) p.failure_strain = k.at("failure_strain");
  p.small_strain = part.section.formulation == Formulation::small_strain;
  p.plane_stress = dimension == 2 && part.plane_stress;
  return p;
}

// The scene reader has checked the curve (exists, starts at volumetric strain 0, strains
// increasing below 1, stresses > 0, at most max_curve_points points) and the formulation
// (total_lagrangian, displacement, not plane stress).
physics::CrushableFoamParameters foam_parameters(const Scene& scene, const MaterialSpec& material) {
  const auto& k = material.constants;
  const auto c = physics::elastic_constants(k.at("youngs_modulus"), k.at("poissons_ratio"));
  physics::CrushableFoamParameters p;
  p.lambda = c.lambda, p.mu = c.mu;
  const CurveSpec* curve = scene.find_curve(material.yield_curve);
  if (!curve) throw std::logic_error("unchecked yield curve " + material.yield_curve);
  for (std::size_t i = 0; i < curve->time.size(); ++i) {
    p.curve_strain[p.curve_points] = curve->time[i];
    p.curve_stress[p.curve_points] = curve->value[i];
    ++p.curve_points;
  }
  if (k.count("tension_cutoff")) p.tension_cutoff = k.at("tension_cutoff");
  return p;
}

// The scene reader has checked the curve (exists, starts at (0, 0), strains increasing below 1,
// stresses not decreasing, at most max_curve_points points), HU in (0, 1], SHAPE > 0, t_c > 0
// and the formulation (total_lagrangian, displacement, not plane stress).
physics::LowDensityFoamParameters ldfoam_parameters(const Scene& scene,
                                                    const MaterialSpec& material) {
  const auto& k = material.constants;
  physics::LowDensityFoamParameters p;
  p.tension_modulus = k.at("youngs_modulus");
  const CurveSpec* curve = scene.find_curve(material.loading_curve);
  if (!curve) throw std::logic_error("unchecked loading curve " + material.loading_curve);
  for (std::size_t i = 0; i < curve->time.size(); ++i) {
    p.curve_strain[p.curve_points] = curve->time[i];
    p.curve_stress[p.curve_points] = curve->value[i];
    ++p.curve_points;
  }
  if (k.count("hysteresis")) p.hysteresis = k.at("hysteresis");
  if (k.count("shape")) p.shape = k.at("shape");
  if (k.count("tension_cutoff")) p.tension_cutoff = k.at("tension_cutoff");
  p.stiffness = physics::ldfoam_stiffness_bound(p);
  return p;
}

}  // namespace

MaterialLaw material_law(const Scene& scene, const PartSpec& part, int dimension) {
  const MaterialSpec& material = *scene.find_material(part.material);
  MaterialLaw law;
  law.elastic = solid_material(material, part, dimension);
  if (material.model == "j2_plasticity") {
    law.plastic = true;
    law.j2 = j2_parameters(scene, material, part, dimension);
  }
  if (material.model == "crushable_foam") {
    law.plastic = law.foam = true;
    law.foam_params = foam_parameters(scene, material);
  }
  if (material.model == "low_density_foam") {
    law.plastic = law.low_density = true;
    law.ldfoam_params = ldfoam_parameters(scene, material);
  }
  if (part.formulation == PartFormulation::mixed_up) {
    // scene/PartFormulationCheck: linear elastic, neo-Hookean or J2, one modulus, plane strain
    // or 3D (the 3D constants), so kappa = lambda + 2 mu / 3. The points keep the deviatoric law.
    law.bulk_modulus = law.elastic.lambda + 2.0 * law.elastic.mu / 3.0;
    if (law.elastic.kind == physics::MaterialKind::neo_hookean)
      law.elastic.kind = physics::MaterialKind::isochoric_neo_hookean;
    else
      law.elastic.lambda = -2.0 * law.elastic.mu / 3.0;
    // J2: the return map acts on the deviatoric stress only and the flow is isochoric, so the
    // law with a zero bulk modulus (lambda = -2 mu / 3) is its deviatoric part exactly, small
    // strain and finite (Hencky: tau = kappa ln J 1 + dev tau, the first term the cells').
    if (law.plastic) law.j2.lambda = -2.0 * law.j2.mu / 3.0;
  }
  return law;
}

}  // namespace efg
