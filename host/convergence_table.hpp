#pragma once
// Results of a refinement study, one row per level: error against grid spacing and against cost.
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <vector>

namespace peristep::host {

struct LevelResult {
  std::uint64_t level = 0, nx = 0, ny = 0;
  double h = 0;             // grid spacing Lx / level
  double errorL2 = 0;       // the component's errorL2 output after the last load increment
  double rate = 0;          // observed order against the previous level (NaN for the first)
  double wallSeconds = 0;   // instantiate to terminate
  double peakRssMb = 0;     // peak resident memory of the process that ran the level
};

// rate_k = log(e_{k-1} / e_k) / log(h_{k-1} / h_k): the exponent p of e ~ C h^p between two levels.
void computeRates(std::vector<LevelResult>& rows);

struct PowerFit {
  double order = 0, constant = 0;  // e ~ constant * h^order, least squares in log-log
};
// Needs two levels or more with positive errors; otherwise order and constant are NaN.
PowerFit fitPowerLaw(const std::vector<LevelResult>& rows);

void writeConvergenceCsv(const std::filesystem::path& file, const std::vector<LevelResult>& rows);
void printConvergenceTable(std::ostream& out, const std::vector<LevelResult>& rows);

}  // namespace peristep::host
