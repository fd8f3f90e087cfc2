// Where a run's files go, checked before anything runs: the results file (and its history CSV)
// must not name an existing folder, and the output folder must be creatable. `efg check` makes
// the same checks without creating anything (issue 14: a result path naming a folder used to be
// found only after the whole run, and hung two ranks).
#pragma once

#include <string>

#include "parallel/Comm.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// The results path for `scene` inside `output_dir`; throws InputError on every rank (naming the
/// scene key) when it or the history path is unusable. Creates the folder when `create` is set.
std::string prepare_output_paths(const CommPtr& comm, const Scene& scene,
                                 const std::string& output_dir, bool create);

}  // namespace efg
