// A finite element stand-in for the meshfree stiffness, the auxiliary space of the iterative
// solver (Xu, "The auxiliary space method and optimal multigrid preconditioning techniques for
// unstructured grids", Computing 56, 1996): the small-strain elastic stiffness of the
// background cells of every part (operators/CellStiffness) on the same nodes, so the same dofs,
// with the part's elastic moduli; the dofs the transformation method constrains are eliminated
// symmetrically (row and column dropped, the collocated row's own diagonal kept), so the matrix
// is symmetric positive definite. Multigrid on it is cheap (27 couplings per node on hexes
// against some 90 of the meshfree rows at dilation 1.5) and scales, and where the meshfree
// integration has no spurious low-energy modes (Gauss cells, SCNI subcells) the two are
// spectrally equivalent:
// with the exact inverse of this matrix as preconditioner GMRES took 12-14 iterations on the
// cantilever block at 297, 1,575 and 9,963 dofs with Gauss cells and 19-22 with subcells; with
// plain SCNI 65 / 120 / 238 (its smoothing points see no strain of nodal modes near the grid's
// highest frequency: the meshfree matrix has energies down to h^2 of the finite elements'
// there). docs/implicit.md, "Auxiliary space".
#pragma once

#include <Tpetra_CrsMatrix.hpp>

#include <string>
#include <vector>

#include "model/Model.hpp"

namespace efg {

/// Empty when the auxiliary space can stand in for the scene's Jacobian at all; otherwise why
/// not: a shell or mixed u-p part, a material without elastic moduli, a condition imposed by
/// penalty or Nitsche (their boundary terms are not in the matrix, which then has no support),
/// contacts or rigid walls (likewise).
std::string auxiliary_space_impossible(const Scene& scene);
/// Empty when the auxiliary space fits every part (the automatic choice then takes it); else
/// why not: auxiliary_space_impossible, or a part integrated by SCNI or direct nodal
/// integration (spurious low-energy modes: iterations grow under refinement).
std::string auxiliary_space_misfit(const Scene& scene);

/// The matrix on K's owned rows (the model's owned dofs): the background cells' stiffness with
/// the dofs of `copied_rows` (local owned rows: the constraint rows, on every rank) eliminated
/// symmetrically, their diagonal K's; K's own row wherever no cell reaches. Collective.
Teuchos::RCP<Tpetra::CrsMatrix<>> auxiliary_stiffness(const Model& model,
                                                      const Tpetra::CrsMatrix<>& K,
                                                      const std::vector<int>& copied_rows);

}  // namespace efg
