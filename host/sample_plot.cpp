#include "sample_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <tuple>

#include "exact_text.hpp"
#include "gnuplot.hpp"
#include "unit_scale.hpp"

namespace peristep::host {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}


struct ErrorCurve {
  std::size_t column = 0;  // gnuplot counts from 1
  std::string label;
};

// The error columns of the study's CSV with something to draw: exact errors from one level on, the
// distance to the last level where it makes a curve (two levels or more besides the last).
std::vector<ErrorCurve> errorCurves(const std::filesystem::path& csv, std::size_t& samplesColumn) {
  std::ifstream in(csv);
  std::string line;
  if (!std::getline(in, line)) return {};
  const std::vector<std::string> header = split(line);
  std::vector<std::size_t> filled(header.size(), 0);  // rows with a value, per column
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    for (std::size_t c = 0; c < cells.size() && c < header.size(); ++c) filled[c] += !cells[c].empty();
  }
  const auto column = [&](const std::string& name, std::size_t least) -> std::size_t {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == name) return filled[c] >= least ? c + 1 : 0;
    return 0;
  };
  samplesColumn = column("samples", 1);
  std::vector<ErrorCurve> curves;
  for (const auto& [name, label, least] : {std::tuple<std::string, std::string, std::size_t>{"errorMean", "mean: error against the exact mean", 1},
                                           {"errorStd", "std: error against the exact std", 1},
                                           {"diffMean", "mean: distance to the last level", 2},
                                           {"diffStd", "std: distance to the last level", 2}})
    if (const std::size_t c = column(name, least)) curves.push_back({c, label});
  return samplesColumn ? curves : std::vector<ErrorCurve>{};
}

void errorPanel(std::ostream& s, const std::filesystem::path& csv, std::size_t samples, const std::vector<ErrorCurve>& curves) {
  s << "set datafile separator ','\nset logscale xy\nset format y '%.0e'\nset format x '%g'\nset key top right\n"
    << "set xlabel 'samples'\nset ylabel 'L2 error of the displacement moment [m]'\nplot ";
  for (std::size_t i = 0; i < curves.size(); ++i)
    s << (i ? ", " : "") << gnuplotQuoted(csv.string()) << " skip 1 using " << samples << ':' << curves[i].column
      << " with linespoints pt 7 title " << gnuplotQuoted(curves[i].label);
  s << "\nunset logscale\nset datafile separator whitespace\n";
}

// A histogram of the samples, the mean and the interval as vertical lines.
void distributionPanel(std::ostream& s, const ResultDistribution& r, std::size_t index) {
  double largest = 0;
  for (double v : r.values) largest = std::max(largest, std::abs(v));
  const ScaledUnit u = scaledUnit(r.unit, std::max({largest, std::abs(r.low), std::abs(r.high)}));
  const auto [lo, hi] = std::minmax_element(r.values.begin(), r.values.end());
  const std::size_t q = r.values.size();
  const std::size_t bins = q < 4 ? q : std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(std::sqrt(double(q)))), 4, 30);
  double width = (*hi - *lo) / static_cast<double>(bins);
  if (!(width > 0)) width = std::max(0.02 * std::abs(*lo), 1e-300);  // every sample alike: one bar
  std::vector<std::size_t> count(bins, 0);
  for (double v : r.values) ++count[std::min(bins - 1, static_cast<std::size_t>((v - *lo) / width))];
  const std::size_t most = *std::max_element(count.begin(), count.end());

  const std::string block = "$result" + std::to_string(index);
  s << block << " << EOD\n";
  for (std::size_t b = 0; b < bins; ++b) s << exactText((*lo + (static_cast<double>(b) + 0.5) * width) * u.factor) << ' ' << count[b] << '\n';
  s << "EOD\n";
  const double top = 1.6 * static_cast<double>(most);  // room for the legend above the bars
  const auto vertical = [&](double x) { return "'+' using (" + exactText(x * u.factor) + "):($0 * " + exactText(top) + ") every ::0::1"; };
  s << "set xlabel " << gnuplotQuoted(axisLabel(r.name, u.unit)) << " noenhanced\n"
    << "set ylabel 'samples'\nset yrange [0:" << exactText(top) << "]\nset format x '%.4g'\nset format y '%g'\n"
    << "set ytics " << std::max<std::size_t>(1, (most + 7) / 8) << "\n"  // whole samples
    << "set key top right opaque noenhanced\nset boxwidth " << exactText(width * u.factor) << "\nset style fill solid 0.8\n"
    << "set samples 2\n"
    << "plot " << block << " using 1:2 with boxes lc rgb '#3b528b' title "
    << gnuplotQuoted(std::to_string(q) + " samples, std " + shortNumber(r.std * u.factor)) << ", \\\n  " << vertical(r.mean)
    << " with lines lw 2 lc rgb '#c00000' title "
    << gnuplotQuoted("mean " + shortNumber(r.mean * u.factor) + (u.unit.empty() ? "" : " " + u.unit));
  if (std::isfinite(r.low) && std::isfinite(r.high))
    s << ", \\\n  " << vertical(r.low) << " with lines lw 1.5 dt 2 lc rgb '#c00000' title "
      << gnuplotQuoted(r.interval + ": " + shortNumber(r.low * u.factor) + " to " + shortNumber(r.high * u.factor)) << ", \\\n  "
      << vertical(r.high) << " with lines lw 1.5 dt 2 lc rgb '#c00000' notitle";
  s << "\nset autoscale y\nset ytics autofreq\nset samples 100\nset key noopaque\n";
}

}  // namespace

unsigned samplePlotWidth(std::size_t panels) { return panels <= 1 ? kSamplePlotWidth : 2 * kSamplePlotWidth - 200; }
unsigned samplePlotHeight(std::size_t panels) { return kSamplePlotHeight * static_cast<unsigned>((panels + 1) / 2); }

std::string plotSampleStudy(const std::filesystem::path& csv, const std::string& title,
                            const std::vector<ResultDistribution>& results) {
  const std::filesystem::path png = std::filesystem::path(csv).replace_extension(".png");
  if (!std::ifstream(csv)) return "no plot: cannot read " + csv.string();
  std::size_t samples = 0;
  const std::vector<ErrorCurve> curves = errorCurves(csv, samples);
  std::vector<const ResultDistribution*> drawn;
  for (const ResultDistribution& r : results)
    if (!r.values.empty()) drawn.push_back(&r);
  const std::size_t panels = (curves.empty() ? 0 : 1) + drawn.size();
  if (panels == 0) return "no plot: " + csv.string() + " has no errors to draw and the study names no result";
  if (!gnuplotAvailable()) return "no plot: gnuplot not on PATH";

  std::ostringstream s;
  s << "set encoding utf8\n"
    << "set terminal pngcairo size " << samplePlotWidth(panels) << ',' << samplePlotHeight(panels) << " font ',10'\n"
    << "set output " << gnuplotQuoted(png.string()) << "\nset grid\n";
  if (panels > 1)
    s << "set multiplot layout " << (panels + 1) / 2 << ",2 title " << gnuplotQuoted(title) << " noenhanced\n";
  else
    s << "set title " << gnuplotQuoted(title) << " noenhanced\n";
  if (!curves.empty()) errorPanel(s, csv, samples, curves);
  for (std::size_t i = 0; i < drawn.size(); ++i) distributionPanel(s, *drawn[i], i);
  if (panels > 1) s << "unset multiplot\n";
  const std::string problem = runGnuplot(s.str(), png);
  return problem.empty() ? "wrote " + png.string() : "no plot: " + problem;
}

}  // namespace peristep::host
