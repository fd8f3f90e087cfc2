// The efg subcommands; each returns normally on success and throws efg errors otherwise.
#pragma once

#include "app/CommandLine.hpp"
#include "parallel/Comm.hpp"

namespace efg {

void run_command(const CommPtr& comm, const CommandLine& cl);
void check_command(const CommPtr& comm, const CommandLine& cl);
void mesh_command(const CommPtr& comm, const CommandLine& cl);
void schema_command();
void study_command(const CommPtr& comm, const CommandLine& cl);

}  // namespace efg
