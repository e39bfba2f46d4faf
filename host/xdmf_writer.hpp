#pragma once
// The XDMF sidecar that lets ParaView open an HDF5 result file with either of its XDMF readers: a
// temporal collection with one 2D structured grid (2DSMesh, XY geometry from /xdmf/xy) per step; each
// field on the grid is a node attribute read from that step's view /xdmf/step_<k>/<name>, the ramped
// input and each scalar output a grid-centred attribute (field data in ParaView) written inline. A
// sample study's file has the same shape, one grid per level.
#include <filesystem>
#include <string>
#include <vector>

#include "result_layout.hpp"

namespace peristep::host {

// hdf5File is written into the DataItems as given: pass a name relative to the .xmf file.
std::string xdmfDocument(const ResultLayout& layout, const std::string& hdf5File, const std::vector<StepScalars>& steps);

// Writes the document through a temporary file and a rename, so a reader never sees half of it.
void writeXdmf(const std::filesystem::path& file, const ResultLayout& layout, const std::string& hdf5File,
               const std::vector<StepScalars>& steps);

// A sample study's file: one grid per level in a temporal collection whose time is the level's sample
// count (ParaView's time steps walk through the levels), each field's statistics as node attributes
// "<statistic>_<field>" read from /level_<L>/<statistic>/<field>, the scalar moments inline.
struct StudyXdmfLevel {
  std::uint64_t level = 0, samples = 0;
  std::vector<std::string> statistics;                  // groups of the level: "mean", "std", ...
  std::vector<std::pair<std::string, double>> scalars;  // e.g. {"mean_toughnessKIC", 1.1e6}
};
std::string studyXdmfDocument(const ResultLayout& layout, const std::string& hdf5File,
                              const std::vector<StudyXdmfLevel>& levels);
void writeStudyXdmf(const std::filesystem::path& file, const ResultLayout& layout, const std::string& hdf5File,
                    const std::vector<StudyXdmfLevel>& levels);

}  // namespace peristep::host
