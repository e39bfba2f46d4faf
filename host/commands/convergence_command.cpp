// `peristep convergence SCENE [--fmu PATH] [--out CSV]`: the scene at every [convergence] level,
// error against grid spacing and cost, as a terminal table, a CSV file and (with gnuplot) a PNG.
#include <cstdio>
#include <iostream>

#include "../gnuplot.hpp"
#include "../gnuplot_plot.hpp"
#include "../host_errors.hpp"
#include "../level_runner.hpp"
#include "../progress.hpp"
#include "../scene_overrides.hpp"
#include "commands.hpp"
#include "opened_fmu.hpp"

namespace peristep::host {

int convergenceCommand(const ConvergenceOptions& options) {
  const OpenedFmu fmu(options.fmu);
  for (const std::string& set : options.set)
    if (const std::string name = parseOverride(set).name; name == "nx" || name == "ny")
      throw InputError("--set " + set + ": a refinement study sets nx and ny from its [convergence] levels");
  const Scene scene = loadScene(options.scene, fmu.md, options.set);
  if (scene.levels.empty())
    throw InputError(options.scene + ": [convergence] levels: missing (e.g. levels = [8, 16, 32, 64])");
  std::filesystem::path csv = options.out.empty() ? scene.csvFile : options.out;
  if (csv.empty()) csv = std::filesystem::path(options.scene).filename().replace_extension(".csv");
  const std::filesystem::path png = std::filesystem::path(csv).replace_extension(".png");

  FmuInstance::Options instanceOptions;
  instanceOptions.resourcePath = fmu.archive.resourcePath();
  instanceOptions.verbose = options.verbose;

  std::vector<LevelResult> rows;
  std::string failure;
  {
    ProgressBar bar("convergence", scene.levels.size());
    for (std::uint64_t level : scene.levels) {
      bar.update(rows.size(), "level " + std::to_string(level));
      try {
        rows.push_back(runLevel(fmu.archive, fmu.md, scene, level, instanceOptions));
      } catch (const RunError& e) {
        failure = e.what();  // finer levels would fail too: report what was measured so far
        break;
      }
    }
  }
  computeRates(rows);
  const PowerFit fit = fitPowerLaw(rows);

  std::cout << "# " << options.scene << ": errorL2 after the last load increment, nx = ny = level + 1\n";
  printConvergenceTable(std::cout, rows);
  if (rows.size() >= 2) {
    char order[32];
    std::snprintf(order, sizeof order, "%.2f", fit.order);
    std::cout << "least-squares order over all levels: " << order << '\n';
  }
  if (!rows.empty()) {
    writeConvergenceCsv(csv, rows);
    std::cout << "wrote " << csv.string();
    if (!gnuplotAvailable()) {
      std::cout << " (gnuplot not on PATH: no plot)\n";
    } else if (const std::string problem = plotConvergence(rows, png, fmu.md.modelName + ": " + options.scene);
               !problem.empty()) {
      std::cout << '\n';
      std::cerr << "peristep: no plot: " << problem << '\n';
    } else {
      std::cout << " and " << png.string() << '\n';
    }
  }
  if (!failure.empty()) throw RunError(failure);
  return 0;
}

}  // namespace peristep::host
