#include "gnuplot_plot.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "gnuplot.hpp"

namespace peristep::host {

namespace {

// Least squares of log(error) against log(x), x being h or wall time: the plot's dashed line.
std::string fitLine(std::vector<LevelResult> rows, bool againstTime, const char* symbol) {
  if (againstTime)
    for (LevelResult& r : rows) r.h = r.wallSeconds;
  const PowerFit fit = fitPowerLaw(rows);
  if (!std::isfinite(fit.order)) return "";
  char line[160];
  std::snprintf(line, sizeof line, ", %.17g * x**%.17g with lines dashtype 2 lc rgb 'black' title 'fit: %s^{%.2f}'",
                fit.constant, fit.order, symbol, fit.order);
  return line;
}

}  // namespace

std::string plotConvergence(const std::vector<LevelResult>& rows, const std::filesystem::path& png, const std::string& title) {
  std::ostringstream script;
  script << "set terminal pngcairo size " << kConvergencePlotWidth << ',' << kConvergencePlotHeight << " font ',10'\n"
         << "set output " << gnuplotQuoted(png.string()) << "\n"
         << "set logscale xy\n"
         << "set format xy '%.0e'\n"
         << "set grid\n"
         << "set key bottom right\n"
         << "set ylabel 'L2 error [m]'\n"
         << "$levels << EOD\n";
  for (const LevelResult& r : rows) {
    char line[96];
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", r.h, r.errorL2, r.wallSeconds);
    script << line;
  }
  script << "EOD\n"
         << "set multiplot layout 1,2 title " << gnuplotQuoted(title) << " noenhanced\n"
         << "set xlabel 'grid spacing h [m]'\n"
         << "plot $levels using 1:2 with linespoints pt 7 title 'errorL2'" << fitLine(rows, false, "h") << "\n"
         << "set xlabel 'wall time per level [s]'\n"
         << "set key top right\n"  // the error falls with cost: the upper right corner is free
         << "plot $levels using 3:2 with linespoints pt 7 title 'errorL2'" << fitLine(rows, true, "t") << "\n"
         << "unset multiplot\n";
  return runGnuplot(script.str(), png);
}

}  // namespace peristep::host
