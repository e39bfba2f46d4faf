#pragma once
// The plot of a refinement study (`peristep convergence`), drawn by gnuplot.
#include <filesystem>
#include <string>
#include <vector>

#include "convergence_table.hpp"

namespace peristep::host {

// Error against grid spacing and against wall time per level, log-log, each with its least-squares
// power law in the legend; kConvergencePlotWidth x kConvergencePlotHeight px. Returns gnuplot's
// complaint, or "" on success.
inline constexpr unsigned kConvergencePlotWidth = 1100, kConvergencePlotHeight = 450;
std::string plotConvergence(const std::vector<LevelResult>& rows, const std::filesystem::path& png, const std::string& title);

}  // namespace peristep::host
