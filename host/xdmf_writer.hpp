#pragma once
// The XDMF 3 sidecar that lets ParaView open an HDF5 result file: a temporal collection with one
// 2D structured grid (2DSMesh, X_Y geometry from /grid/x and /grid/y) per step; each field on the
// grid is a node attribute selected from /fields/<name> by a hyperslab, each scalar output a
// grid-centred attribute from /scalars/<name>.
#include <filesystem>
#include <string>
#include <vector>

#include "result_layout.hpp"

namespace peristep::host {

// hdf5File is written into the DataItems as given: pass a name relative to the .xmf file.
std::string xdmfDocument(const ResultLayout& layout, const std::string& hdf5File, const std::vector<double>& times);

// Writes the document through a temporary file and a rename, so a reader never sees half of it.
void writeXdmf(const std::filesystem::path& file, const ResultLayout& layout, const std::string& hdf5File,
               const std::vector<double>& times);

}  // namespace peristep::host
