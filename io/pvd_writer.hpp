// ParaView data collection (.pvd): the list of a run's snapshot files, each with the physical
// time it holds, so that ParaView opens the series as one time-dependent source and plays it in
// simulation time (not in file order with unit steps). Format: a VTKFile of type "Collection",
// one <DataSet timestep=".." file=".."/> per snapshot, file names relative to the .pvd.
#pragma once

#include <string>
#include <vector>

namespace sphdeck::io {

struct PvdEntry {
    double time = 0;
    std::string file;  // relative to the .pvd's folder
};

// Writes `path` (times at shortest round-trip precision); throws std::runtime_error naming the
// file when it cannot be written.
void write_pvd_file(const std::string& path, const std::vector<PvdEntry>& entries);

}  // namespace sphdeck::io
