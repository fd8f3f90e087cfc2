// Scene keys of the mesh (mesh.file, mesh.generate and mesh.more_blocks; scene/MeshInput reads
// and cross-checks them).
#pragma once

#include "scene/Schema.hpp"

namespace efg {

schema::SpecPtr mesh_spec();

}  // namespace efg
