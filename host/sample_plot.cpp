#include "sample_plot.hpp"

#include <fstream>
#include <sstream>
#include <vector>

#include "gnuplot.hpp"

namespace peristep::host {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

}  // namespace

std::string plotSampleStudy(const std::filesystem::path& csv, const std::string& title) {
  const std::filesystem::path png = std::filesystem::path(csv).replace_extension(".png");
  std::ifstream in(csv);
  std::string line;
  if (!std::getline(in, line)) return "no plot: cannot read " + csv.string();
  const std::vector<std::string> header = split(line);
  std::vector<std::size_t> filled(header.size(), 0);  // rows with a value, per column
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    for (std::size_t c = 0; c < cells.size() && c < header.size(); ++c) filled[c] += !cells[c].empty();
  }
  const auto column = [&](const std::string& name) -> std::size_t {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == name) return filled[c] > 0 ? c + 1 : 0;  // gnuplot counts from 1
    return 0;
  };
  const std::size_t samples = column("samples");
  std::vector<std::pair<std::size_t, std::string>> curves;
  for (const auto& [name, label] : {std::pair<std::string, std::string>{"errorMean", "mean: error against the exact mean"},
                                    {"errorStd", "std: error against the exact std"},
                                    {"diffMean", "mean: distance to the last level"},
                                    {"diffStd", "std: distance to the last level"}})
    if (const std::size_t c = column(name)) curves.emplace_back(c, label);
  if (!samples || curves.empty()) return "no plot: " + csv.string() + " has no errors to draw";
  if (!gnuplotAvailable()) return "no plot: gnuplot not on PATH";

  std::ostringstream s;
  s << "set terminal pngcairo size " << kSamplePlotWidth << ',' << kSamplePlotHeight << " font ',10'\n"
    << "set output " << gnuplotQuoted(png.string()) << "\n"
    << "set datafile separator ','\nset logscale xy\nset format y '%.0e'\nset grid\nset key top right noenhanced\n"
    << "set title " << gnuplotQuoted(title) << " noenhanced\n"
    << "set xlabel 'samples'\nset ylabel 'L2 error of the displacement moment [m]'\n"
    << "plot ";
  for (std::size_t i = 0; i < curves.size(); ++i)
    s << (i ? ", " : "") << gnuplotQuoted(csv.string()) << " skip 1 using " << samples << ':' << curves[i].first
      << " with linespoints pt 7 title " << gnuplotQuoted(curves[i].second);
  s << '\n';
  const std::string problem = runGnuplot(s.str());
  return problem.empty() ? "wrote " + png.string() : "no plot: " + problem;
}

}  // namespace peristep::host
