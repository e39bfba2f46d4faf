#include "convergence_table.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>

#include "atomic_file.hpp"
#include "host_errors.hpp"
#include "progress.hpp"

namespace peristep::host {

void computeRates(std::vector<LevelResult>& rows) {
  for (std::size_t k = 0; k < rows.size(); ++k)
    rows[k].rate = k == 0 ? std::numeric_limits<double>::quiet_NaN()
                          : std::log(rows[k - 1].errorL2 / rows[k].errorL2) / std::log(rows[k - 1].h / rows[k].h);
}

PowerFit fitPowerLaw(const std::vector<LevelResult>& rows) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const LevelResult& r : rows) {
    if (!(r.errorL2 > 0) || !(r.h > 0)) continue;
    const double x = std::log(r.h), y = std::log(r.errorL2);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double denominator = n * sxx - sx * sx;
  if (n < 2 || denominator == 0) return {nan, nan};
  const double order = (n * sxy - sx * sy) / denominator;
  return {order, std::exp((sy - order * sx) / n)};
}

void writeConvergenceCsv(const std::filesystem::path& file, const std::vector<LevelResult>& rows) {
  std::ostringstream out;
  out << "level,nx,ny,h,points,error_l2,rate,wall_s,peak_rss_mb\n";
  char line[256];
  for (const LevelResult& r : rows) {
    std::snprintf(line, sizeof line, "%llu,%llu,%llu,%.17g,%llu,%.17g,%.17g,%.6f,%.1f\n",
                  static_cast<unsigned long long>(r.level), static_cast<unsigned long long>(r.nx),
                  static_cast<unsigned long long>(r.ny), r.h, static_cast<unsigned long long>(r.nx * r.ny), r.errorL2,
                  r.rate, r.wallSeconds, r.peakRssMb);
    out << line;
  }
  writeFileAtomically(file, out.str());
}

void printConvergenceTable(std::ostream& out, const std::vector<LevelResult>& rows) {
  std::vector<std::vector<std::string>> cells;
  for (const LevelResult& r : rows) {
    char rate[16] = "-", wall[32], memory[32];
    if (!std::isnan(r.rate)) std::snprintf(rate, sizeof rate, "%.2f", r.rate);
    std::snprintf(wall, sizeof wall, "%.3f", r.wallSeconds);
    std::snprintf(memory, sizeof memory, "%.0f", r.peakRssMb);
    cells.push_back({std::to_string(r.level), std::to_string(r.nx) + " x " + std::to_string(r.ny),
                     formatNumber(r.h), formatNumber(r.errorL2), rate, wall, memory});
  }
  printTable(out, {"level", "points", "h", "L2 error", "rate", "wall s", "peak MB"}, cells);
}

}  // namespace peristep::host
