// Which parts may carry a pressure field (parts[].formulation: mixed_up): the condensed cell
// pressure of operators/MixedPressure splits the linear elastic (small strain) and neo-Hookean
// (finite strain) laws into a deviatoric part at the integration points and a volumetric part per
// background cell; J2 plasticity is not split yet.
#pragma once

#include "scene/Scene.hpp"

namespace efg {

/// Throws InputError at file:line:col of parts[i].formulation when a mixed_up part's material is
/// neither linear_elastic nor neo_hookean or has a graded Young's modulus (the cell's bulk modulus is one number), and
/// at output.fields when cell_pressure is asked of a scene without mixed_up parts.
void check_part_formulations(const Scene& scene);

}  // namespace efg
