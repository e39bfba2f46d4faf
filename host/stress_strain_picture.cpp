#include "stress_strain_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "exact_text.hpp"
#include "gnuplot.hpp"
#include "unit_scale.hpp"

namespace peristep::host {

namespace {

std::optional<std::size_t> scalarIndex(const ResultLayout& layout, const std::string& name) {
  for (std::size_t i = 0; i < layout.scalars.size(); ++i)
    if (layout.scalars[i].name == name) return i;
  return std::nullopt;
}

bool changes(const std::vector<StepScalars>& history, std::size_t i) {
  for (const StepScalars& s : history)
    if (s.scalars[i] != history.front().scalars[i]) return true;
  return false;
}


}  // namespace

bool isBarRun(const ResultLayout& layout, const std::vector<StepScalars>& history) {
  const auto stress = scalarIndex(layout, "barStress"), strain = scalarIndex(layout, "barStrain");
  return stress && strain && !history.empty() && changes(history, *stress) && changes(history, *strain);
}

std::string writeStressStrainPicture(const std::filesystem::path& png, const ResultLayout& layout,
                                     const std::vector<StepScalars>& history, const std::string& title) {
  if (!isBarRun(layout, history)) return "no bar stress and strain in the run";
  const std::size_t stress = *scalarIndex(layout, "barStress"), strain = *scalarIndex(layout, "barStrain");
  double largestStress = 0, largestStrain = 0;
  for (const StepScalars& s : history)
    largestStress = std::max(largestStress, std::abs(s.scalars[stress])),
    largestStrain = std::max(largestStrain, std::abs(s.scalars[strain]));
  const ScaledUnit sigma = scaledUnit(layout.scalars[stress].unit, largestStress);
  // Strain in per cent where it stays below 10% (a bar's strain of 0.004 reads as 0.4%).
  const bool percent = largestStrain < 0.1;

  // n' and K' of the cyclic fit, once computed (zero before the protocol's last step).
  std::string fit;
  const auto exponent = scalarIndex(layout, "cyclicExponent"), coefficient = scalarIndex(layout, "cyclicCoefficient");
  if (exponent && coefficient && history.back().scalars[*exponent] != 0) {
    const double k = history.back().scalars[*coefficient];
    const ScaledUnit kUnit = scaledUnit(layout.scalars[*coefficient].unit, std::abs(k));
    fit = "cyclic fit: n' = " + shortNumber(history.back().scalars[*exponent]) + ", K' = " + shortNumber(k * kUnit.factor) +
          (kUnit.unit.empty() ? "" : " " + kUnit.unit);
  }

  std::ostringstream s;
  s << "set encoding utf8\n"
    << "set terminal pngcairo size 900,600 font ',11'\n"
    << "set output " << gnuplotQuoted(png.string()) << "\n"
    << "set title " << gnuplotQuoted(title) << " noenhanced\n"
    << "set grid\nset key below noenhanced\nset format x '%.4g'\nset format y '%.4g'\n"
    << "set xlabel " << gnuplotQuoted(percent ? "strain u(L)/L [%]" : "strain u(L)/L [-]") << "\n"
    << "set ylabel " << gnuplotQuoted(axisLabel("stress F/A", sigma.unit)) << "\n"
    << "$path << EOD\n";
  for (const StepScalars& step : history)
    s << exactText(step.scalars[strain] * (percent ? 100 : 1)) << ' ' << exactText(step.scalars[stress] * sigma.factor) << '\n';
  s << "EOD\n"
    << "plot $path using 1:2 with linespoints pt 7 ps 0.5 lc rgb '#3b528b' title "
    << gnuplotQuoted("bar end, " + std::to_string(history.size()) + " steps");
  if (!fit.empty()) s << ", NaN with lines lc rgb 'white' title " << gnuplotQuoted(fit);
  s << '\n';
  return runGnuplot(s.str(), png);
}

}  // namespace peristep::host
