#pragma once
// A PNG of a refinement study drawn by gnuplot (when it is installed): error against grid spacing
// with the least-squares power law, and error against wall time.
#include <filesystem>
#include <string>

#include "convergence_table.hpp"

namespace peristep::host {

// Looks for an executable `gnuplot` on PATH.
bool gnuplotAvailable();

// Reads the CSV written by writeConvergenceCsv. Returns gnuplot's complaint, or "" on success:
// a missing plot is worth a warning, not a failed study.
std::string plotConvergence(const std::filesystem::path& csv, const std::filesystem::path& png, const PowerFit& fit,
                            const std::string& title);

}  // namespace peristep::host
