// Penalty contact between deformable parts in explicit stages (LS-DYNA's automatic
// surface-to-surface contact in meshfree form). A candidate is an owned surface particle J of
// the contact's `parts`, at its physical position x_J = X_J + sum_I phi_I(X_J) d_I; the target
// is the current surface of the `target_parts`: their boundary facets (contact/SurfaceFacets)
// through their surface particles' physical positions, gathered on every rank each evaluation.
// Search: facet bins over the current positions (contact/FacetBins), rebuilt when a target
// node has moved by more than a tenth of the smallest facet since the last build.
// The facet J presses into (contact/FacetProjection; chosen by SurfaceContact::choose_facet)
// decides: inside (gap g < 0, -g below the facet's reference size),
//   F = max(0, k (-g) - c v_n) n + F_t,   k = penalty x m_J / dt^2,  c = damping x sqrt(k m_J)
// (two-way; sqrt(2) x that one-way: `damping` is the fraction of critical of two facing
// particles' relative motion),
// v_n and the slip increment taken relative to the facet's point (the facet's nodes' motion
// since the last commit, weighted), F_t the Coulomb return map of contact/CoulombFriction.hpp.
// F acts on J through its shape-function row and -w_a F on the facet's surface particles a
// (weights w summing to one, spread through their rows): momentum is conserved to round-off.
// With two_way (default) the target parts' surface particles are candidates against the parts'
// surface too, so neither side passes through the other's facets.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "contact/CoulombFriction.hpp"
#include "contact/FacetBins.hpp"
#include "contact/FacetProjection.hpp"
#include "contact/ParticleRow.hpp"
#include "contact/SurfaceFacets.hpp"

namespace efg {

class SurfaceContact {
 public:
  SurfaceContact(const ModelOperators& ops, const Vector& mass_owned, const std::string& stage);
  /// Does the scene have a contact between deformable parts?
  static bool wanted(const Scene& scene);

  /// The friction reference: the positions at a stage start.
  void start(const Vector& d_overlap);
  /// Adds the contact forces at d to f_overlap. Collective.
  void add_forces(const Vector& d_overlap, double dt, Vector& f_overlap);
  /// The step is accepted: the last evaluation becomes the friction reference.
  void commit();
  /// Per contact between deformable parts (scene order), the force of its parts on its target
  /// parts at the last evaluation, 3 components each (summed over ranks).
  const std::vector<double>& forces() const { return forces_; }
  /// Particles in contact at the last evaluation, summed over ranks (collective).
  long long active_count() const;
  /// Candidates tested, summed over ranks (collective).
  long long candidate_count() const;

 private:
  /// The surface of some parts as the contact sees it: facets, the owned surface particles'
  /// rows, and every surface node's position (gathered over ranks) and unit normal (the
  /// facets' normals around it, by length / area).
  struct Surface {
    SurfaceFacets facets;
    std::vector<ParticleRow> rows;                     ///< the owned surface particles
    std::vector<int> row_node;                         ///< their surface node indices
    std::vector<std::array<std::size_t, 2>> particle;  ///< their (part, owned particle)
    std::vector<double> x, x_old, normal;              ///< 3 per surface node
    std::vector<double> mine;                          ///< this rank's positions before the gather

    /// The current positions of facet f's nodes.
    void corners(std::size_t f, double (&corner)[3][3]) const {
      const auto per = static_cast<std::size_t>(facets.nodes_per_facet);
      for (std::size_t a = 0; a < per; ++a)
        for (std::size_t k = 0; k < 3; ++k)
          corner[a][k] = x[3 * static_cast<std::size_t>(facets.facet[f * per + a]) + k];
    }
  };
  struct Candidate {
    std::size_t row = 0;  ///< into own.rows
    double mass = 0;
    std::array<double, 3> ft_old{}, ft_new{};
    bool active = false;
    int facet = -1, facet_old = -1;  ///< the facet pressed into (last evaluation, accepted step)
  };
  struct Pair {
    std::size_t contact = 0;  ///< index among the scene's contacts between deformable parts
    double sign = 1;          ///< +1: candidates of the parts; -1: of the target parts
    double penalty = 0, damping = 0;
    contact::Friction friction;
    std::size_t own = 0, target = 0;  ///< surfaces_: the candidates' and the one they press into
    std::vector<Candidate> candidates;
    std::vector<double> lower, upper, reaction, reaction_sum;
    contact::FacetBins bins;
    std::vector<double> x_binned;  ///< the target's positions at the last bin build
    double bin_margin = 0;
  };
  Surface make_surface(const ModelOperators& ops, const std::vector<std::string>& parts) const;
  void gather(Surface& surface, const Vector& d_overlap) const;
  void build_bins(Pair& pair) const;
  std::pair<int, contact::FacetPoint> choose_facet(const Pair& pair, const Candidate& c) const;

  int dim_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::vector<Surface> surfaces_;  ///< each gathered once per evaluation (two-way: shared)
  std::vector<Pair> pairs_;
  std::vector<double> forces_;
};

}  // namespace efg
