// The communicator type efg passes around (Teuchos' MPI wrapper, as Tpetra uses).
#pragma once

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

namespace efg {
using CommPtr = Teuchos::RCP<const Teuchos::Comm<int>>;
}  // namespace efg
