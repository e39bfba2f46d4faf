#pragma once
// The history of a run's scalar outputs, next to its HDF5 file: <name>.csv (step, time, the ramped
// input, every scalar output) and <name>_history.png drawn by gnuplot. The plot's x axis is the
// quantity the input ramps when it changes from step to step (load_quantity.hpp: the opening of the
// glass-ceramic, a specimen's grip displacement), the step where the component ignores its input (the
// gamut bar's cyclic protocol), otherwise the time (energies of the dynamic scenes); outputs that
// change share a panel when they share a unit (strain, kinetic, fracture energy and external work
// together), each unitless one has its own; every axis in the unit prefix that suits its values.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "result_layout.hpp"

namespace peristep::host {

void writeHistoryCsv(const std::filesystem::path& file, const ResultLayout& layout, const std::vector<StepScalars>& steps);

// Indices into layout.scalars, one list per panel; outputs constant over the run are left out.
std::vector<std::vector<std::size_t>> historyPanels(const ResultLayout& layout, const std::vector<StepScalars>& steps);

// The x axis: its label ("loadDisplacement [µm]", "time [µs]", "step") and the value of each step in
// the label's unit.
struct HistoryAxis {
  std::string label;
  std::vector<double> values;
};
HistoryAxis historyXAxis(const ResultLayout& layout, const std::vector<StepScalars>& steps, const std::string& inputUnit);

// Two panels per row (one when there is one), kHistoryPanelHeight px each, kHistoryPlotWidth wide.
inline constexpr unsigned kHistoryPlotWidth = 1100, kHistoryPanelHeight = 340;
unsigned historyPlotHeight(std::size_t panels);

// Returns "" or why nothing was drawn (no output changes, gnuplot failed).
std::string plotHistory(const std::filesystem::path& png, const ResultLayout& layout, const std::vector<StepScalars>& steps,
                        const std::string& title, const std::string& inputUnit);

}  // namespace peristep::host
