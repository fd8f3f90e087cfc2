// Ghosts for the implicit contact between deformable parts (contact/ImplicitSurfaceContact). A
// touching pair's tangent couples the pressing particle's shape-function row with the rows of
// the facet's particles, which may be owned by any rank; the pair is assembled on the pressing
// particle's rank. So every rank holds, as ghosts, the row nodes of every surface particle of
// those contacts' parts (the exact union of the rows, gathered over ranks): it can then evaluate
// any surface particle's position from its own overlap values and assemble any pair. Built only
// when such a contact acts in an implicit stage; a band of a few particles around the contact
// surfaces, replicated (docs/contact.md states the cost). On a rank's part of a mesh read in
// slices the band's nodes beyond the part are remote ghosts: overlap entries without a mesh node
// (their rows come from their owners, contact/ImplicitSurfaceContact).
#pragma once

#include <vector>

#include "model/Model.hpp"

namespace efg {

/// The contact is between deformable parts and acts in some implicit stage.
bool acts_between_parts_implicitly(const Scene& scene, const ContactSpec& contact);

struct ContactRowGhosts {
  std::vector<LocalIndex> held;     ///< mesh nodes of this rank (its part), ascending
  std::vector<GlobalIndex> remote;  ///< whole-mesh indices of nodes its part does not hold
};

/// The row nodes of the surface particles of the parts of such contacts that this rank does not
/// own, ascending (none without such contacts). Collective.
ContactRowGhosts contact_row_ghosts(const CommPtr& comm, const Model& model);

}  // namespace efg
