// Penalty contact between deformable parts in implicit (static) stages, with Coulomb friction:
// the implicit counterpart of contact/SurfaceContact. Candidates are the owned surface particles of
// the contact's `parts` (and, two-way, of its `target_parts`) at their physical positions
// x_J = X_J + sum_I phi_I(X_J) d_I; a candidate presses into the facet of the other surface that
// contact::choose_facet picks (contact history within a load step: the facet of the last
// accepted step while it still holds). The force pair of contact/PairPenalty.hpp,
//   F_J = k_J (-g) n,  F_a = -w_a F_J,  k_J = implicit_penalty E / h_J A_J
// (contact/BoundaryShares.hpp: the material's stiffness over the boundary spacing, as with
// rigid bodies), acts on J through its row and on the facet's particles a through theirs:
// r -= phi F. Tangent: dr/dd = -sum_P sum_Q phi_P dF_P/dx_Q phi_Q^T over the points P, Q of the
// pair (the particle and the facet's nodes), dF/dx by forward AD (Sacado) of the pair's force:
// the full node-to-segment tangent (gap, normal and weights), nonsymmetric.
// Friction (contact/PairPenalty.hpp's PairFriction): the slip since the last accepted load step
// is the particle's motion relative to the facet's point, the tangential force the Coulomb
// return map's from the committed one with the stick stiffness k_t = E A_J / h_J (the normal
// penalty without implicit_penalty, as with rigid bodies), committed with the step; its
// derivatives, the stick and the slip branches alike, are in the AD tangent too.
//
// Every rank holds the rows of every surface particle of these parts (model/ContactGhosts
// makes their nodes ghosts), so positions, normals and the facet search are local, and a pair
// is assembled on its candidate's rank into its overlap rows. The stiffness graph holds, per
// candidate, the facets it may reach: those whose capture boxes (contact::facet_capture_box)
// grown by one facet size hold it, from the stage start and from each accepted load step;
// when that set grows, the graph is rebuilt before the next load step (refresh_couplings). A
// pair that comes into reach within one load step beyond that margin still acts in the
// residual; its tangent entries outside the graph are dropped for that step (counted).
#pragma once

#include <string>
#include <vector>

#include "contact/FacetBins.hpp"
#include "contact/PairPenalty.hpp"
#include "contact/ParticleRow.hpp"
#include "contact/SurfaceFacets.hpp"
#include "operators/CouplingGraph.hpp"
#include "operators/ModelOperators.hpp"

namespace efg {

class ImplicitSurfaceContact {
 public:
  explicit ImplicitSurfaceContact(const ModelOperators& ops);
  /// Some contact between deformable parts acts in an implicit stage of the scene.
  static bool wanted(const Scene& scene);

  /// A stage begins: the contacts acting in it, no contact history; the friction's reference
  /// is the state at d (collective only in that it reads d).
  void begin_stage(const std::string& stage, const Vector& d_overlap, double t0);
  /// The load level's time (friction's decay law takes the slip rate over the load step).
  void set_time(double t) { t_ = t; }
  /// Adds, per candidate, the facets within reach at d to its couplings. True when any rank's
  /// couplings grew (the graph must be rebuilt). Collective.
  bool refresh_couplings(const Vector& d_overlap);
  void add_couplings(CouplingGraph& graph) const;
  /// r -= phi F (overlap) at d.
  void add_residual(const Vector& d_overlap, Vector& r_overlap) const;
  /// K += dr/dd (assembly mode).
  void add_tangent(const Vector& d_overlap, FEMatrix& K) const;
  /// The load step at d is accepted: its facets become the contact history, its positions and
  /// tangential forces the friction's reference.
  void commit(const Vector& d_overlap);
  /// Per contact between deformable parts (scene order, as SurfaceContact::forces), the force
  /// of its parts on its target parts at d, 3 components each (summed over ranks; collective).
  std::vector<double> forces(const Vector& d_overlap) const;
  /// Tangent entries that fell outside the graph since the last call (this rank).
  long long take_dropped() const {
    const auto n = dropped_;
    dropped_ = 0;
    return n;
  }

 private:
  /// The surface of some parts: its facets and every surface particle's row (all ranks').
  struct Surface {
    SurfaceFacets facets;
    std::vector<ParticleRow> rows;  ///< per surface node, overlap node ids
    std::vector<double> x, normal;  ///< 3 per surface node at the last evaluation
    std::vector<double> x_old;      ///< 3 per surface node at the last accepted load step
    void corners(std::size_t f, double (&corner)[3][3]) const;
  };
  struct Candidate {
    std::size_t node = 0;          ///< surface node of its own surface (owned here)
    double stiffness = 0;          ///< k_J = implicit_penalty E / h_J A_J
    int facet_old = -1;            ///< the facet pressed into at the last accepted load step
    double ft_old[3] = {0, 0, 0};  ///< its committed tangential force (friction)
    std::vector<int> coupled;      ///< facets in the stiffness graph with it, ascending
  };
  struct Pair {
    std::size_t contact = 0;  ///< index among the scene's contacts between deformable parts
    const ContactSpec* spec = nullptr;
    double sign = 1;  ///< +1: candidates of the parts; -1: of the target parts
    std::size_t own = 0, target = 0;
    bool active = false;
    contact::Friction friction;
    std::vector<Candidate> candidates;
    bool rubs() const { return friction.mu_s > 0 || friction.mu_d > 0; }
    mutable contact::FacetBins bins;
  };
  /// A candidate pressing into a facet: its facet (-1: none) and the points' forces.
  struct Press {
    int facet = -1;
    double force[4][3] = {};
    double ft[3] = {0, 0, 0};  ///< the tangential force (friction)
  };
  /// The pair's friction data for candidate c pressing into `facet` (null without friction);
  /// corner_old receives the facet's nodes at the last accepted step.
  const contact::PairFriction* friction_of(const Pair& pair, const Candidate& c, int facet,
                                           double (&corner_old)[3][3],
                                           contact::PairFriction& out) const;

  Surface make_surface(const ModelOperators& ops, const std::vector<std::string>& parts) const;
  /// Positions and normals of every surface at d, and each active pair's facet bins (grown by
  /// `reach` facet sizes beyond the capture box).
  void evaluate(const Vector& d_overlap, double reach) const;
  Press press(const Pair& pair, const Candidate& c) const;
  /// The rows of a pair's points: the candidate's, then the facet's nodes'.
  std::vector<const ParticleRow*> rows_of(const Pair& pair, const Candidate& c, int facet) const;

  int dim_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  mutable std::vector<Surface> surfaces_;
  std::vector<Pair> pairs_;
  std::size_t contact_count_ = 0;
  double t_ = 0, t_committed_ = 0;
  mutable long long dropped_ = 0;
};

}  // namespace efg
