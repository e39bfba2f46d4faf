#include "run_history.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "atomic_file.hpp"
#include "exact_text.hpp"
#include "gnuplot.hpp"
#include "host_errors.hpp"
#include "load_quantity.hpp"
#include "unit_scale.hpp"

namespace peristep::host {

namespace {

bool inputVaries(const std::vector<StepScalars>& steps) {
  for (const StepScalars& s : steps)
    if (s.input != steps.front().input) return true;
  return false;
}


}  // namespace

void writeHistoryCsv(const std::filesystem::path& file, const ResultLayout& layout, const std::vector<StepScalars>& steps) {
  std::ostringstream out;
  out << "step,time" << (layout.inputName.empty() ? "" : "," + layout.inputName);
  for (const ArrayInfo& s : layout.scalars) out << ',' << s.name;
  out << '\n';
  for (std::size_t k = 0; k < steps.size(); ++k) {
    out << k + 1 << ',' << exactText(steps[k].time);
    if (!layout.inputName.empty()) out << ',' << exactText(steps[k].input);
    for (double v : steps[k].scalars) out << ',' << exactText(v);
    out << '\n';
  }
  writeFileAtomically(file, out.str());
}

std::vector<std::vector<std::size_t>> historyPanels(const ResultLayout& layout, const std::vector<StepScalars>& steps) {
  std::vector<std::vector<std::size_t>> panels;
  std::map<std::string, std::size_t> panelOfUnit;
  for (std::size_t i = 0; i < layout.scalars.size(); ++i) {
    bool changes = false;
    for (const StepScalars& s : steps) changes |= s.scalars[i] != steps.front().scalars[i];
    if (!changes) continue;
    const std::string& unit = layout.scalars[i].unit;
    if (!unit.empty()) {
      if (const auto it = panelOfUnit.find(unit); it != panelOfUnit.end()) {
        panels[it->second].push_back(i);
        continue;
      }
      panelOfUnit[unit] = panels.size();
    }
    panels.push_back({i});
  }
  return panels;
}

unsigned historyPlotHeight(std::size_t panels) {
  return kHistoryPanelHeight * static_cast<unsigned>((panels + 1) / 2) + 40;  // + the overall title
}

HistoryAxis historyXAxis(const ResultLayout& layout, const std::vector<StepScalars>& steps, const std::string& inputUnit) {
  const LoadQuantity load = loadQuantity(layout, inputUnit);
  const bool againstStep = !layout.inputName.empty() && load.unused;
  const bool againstInput = !layout.inputName.empty() && !load.unused && inputVaries(steps);
  HistoryAxis axis;
  for (std::size_t k = 0; k < steps.size(); ++k)
    axis.values.push_back(againstStep ? static_cast<double>(k + 1) : againstInput ? load.perInput * steps[k].input : steps[k].time);
  if (againstStep) {
    axis.label = "step";
    return axis;
  }
  double largest = 0;
  for (double v : axis.values) largest = std::max(largest, std::abs(v));
  const ScaledUnit unit = scaledUnit(againstInput ? load.unit : "s", largest);
  for (double& v : axis.values) v *= unit.factor;
  axis.label = axisLabel(againstInput ? load.name : "time", unit.unit);
  return axis;
}

std::string plotHistory(const std::filesystem::path& png, const ResultLayout& layout, const std::vector<StepScalars>& steps,
                        const std::string& title, const std::string& inputUnit) {
  const auto panels = historyPanels(layout, steps);
  if (panels.empty()) return "no output changes during the run";
  const HistoryAxis x = historyXAxis(layout, steps, inputUnit);
  std::ostringstream s;
  s << "set encoding utf8\n"
    << "set terminal pngcairo size " << kHistoryPlotWidth << ',' << historyPlotHeight(panels.size()) << " font ',10'\n"
    << "set output " << gnuplotQuoted(png.string()) << "\n"
    << "set grid\nset format y '%.4g'\nset format x '%.4g'\n"
    << "$steps << EOD\n";
  for (std::size_t k = 0; k < steps.size(); ++k) {
    s << exactText(x.values[k]);
    for (double v : steps[k].scalars) s << ' ' << exactText(v);
    s << '\n';
  }
  s << "EOD\n"
    << "set multiplot layout " << (panels.size() + 1) / 2 << ',' << std::min<std::size_t>(panels.size(), 2) << " title " << gnuplotQuoted(title) << " noenhanced\n"
    << "set xlabel " << gnuplotQuoted(x.label) << " noenhanced\n";
  for (const auto& panel : panels) {
    // One unit per panel, with the prefix that suits its largest value.
    double largest = 0;
    for (std::size_t i : panel)
      for (const StepScalars& step : steps) largest = std::max(largest, std::abs(step.scalars[i]));
    const ScaledUnit y = scaledUnit(layout.scalars[panel.front()].unit, largest);
    s << "set ylabel " << gnuplotQuoted(panel.size() == 1 ? axisLabel(layout.scalars[panel.front()].name, y.unit) : "[" + y.unit + "]")
      << " noenhanced\n"
      // A lone curve is named by its axis; several get a key beside the plot, where it hides no data.
      << (panel.size() == 1 ? "unset key\n" : "set key outside right top vertical noenhanced\n") << "plot ";
    for (std::size_t c = 0; c < panel.size(); ++c)
      s << (c ? ", " : "") << "$steps using 1:($" << panel[c] + 2 << "*" << exactText(y.factor) << ") with linespoints pt 7 ps 0.6 title "
        << gnuplotQuoted(layout.scalars[panel[c]].name);
    s << '\n';
  }
  s << "unset multiplot\n";
  return runGnuplot(s.str(), png);
}

}  // namespace peristep::host
