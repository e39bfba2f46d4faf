// `peristep run [SCENE] [--fmu PATH] [--out FILE] [--set NAME=VALUE]...`: one loading scenario, results
// to HDF5 + XDMF, the history of the scalar outputs to CSV, a picture of the last step (of a bar: its
// stress-strain path) and a plot of the history (gnuplot).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>
#include <variant>

#include "../fmu_loader.hpp"
#include "../gnuplot.hpp"
#include "../host_errors.hpp"
#include "../output_lock.hpp"
#include "../progress.hpp"
#include "../result_files.hpp"
#include "../run_history.hpp"
#include "../run_picture.hpp"
#include "../stress_strain_picture.hpp"
#include "../simulation.hpp"
#include "commands.hpp"
#include "opened_fmu.hpp"

namespace peristep::host {

namespace {

std::filesystem::path outputPath(const RunOptions& options, const Scene& scene) {
  if (!options.out.empty()) return options.out;
  if (!scene.outputFile.empty()) return scene.outputFile;
  return options.scene.empty() ? std::filesystem::path("peristep_run.h5")
                               : std::filesystem::path(options.scene).filename().replace_extension(".h5");
}

// One row per step, leaving out scalar outputs that stayed zero throughout (the scene does not
// compute them) and naming them below instead; long runs show their first and last steps.
void printSummary(const ResultLayout& layout, const std::vector<StepValues>& steps) {
  std::vector<std::string> header{"step", "time"};
  if (!layout.inputName.empty()) header.push_back(layout.inputName);
  std::vector<std::size_t> shown;
  std::string zero;
  for (std::size_t i = 0; i < layout.scalars.size(); ++i) {
    bool allZero = true;
    for (const StepValues& s : steps) allZero &= s.scalars[i] == 0.0;
    if (allZero) zero += (zero.empty() ? "" : ", ") + layout.scalars[i].name;
    else shown.push_back(i), header.push_back(layout.scalars[i].name);
  }
  std::vector<std::vector<std::string>> rows;
  constexpr std::size_t kEdge = 6;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    if (steps.size() > 2 * kEdge + 1 && k == kEdge) rows.push_back({"..."});
    if (steps.size() > 2 * kEdge + 1 && k >= kEdge && k < steps.size() - kEdge) continue;
    const StepValues& s = steps[k];
    std::vector<std::string> row{std::to_string(k + 1), formatNumber(s.time)};
    if (!layout.inputName.empty()) row.push_back(formatNumber(s.input));
    for (std::size_t i : shown) row.push_back(formatNumber(s.scalars[i]));
    rows.push_back(row);
  }
  printTable(std::cout, header, rows);
  if (!zero.empty()) std::cout << "zero at every step (not computed by this scene): " << zero << '\n';
}

void checkFinite(const StepValues& step, const ResultLayout& layout, std::uint64_t index) {
  const auto complain = [&](const std::string& name) {
    throw RunError("step " + std::to_string(index) + ": output " + name + " is not finite");
  };
  for (std::size_t i = 0; i < step.scalars.size(); ++i)
    if (!std::isfinite(step.scalars[i])) complain(layout.scalars[i].name);
  for (std::size_t i = 0; i < step.fields.size(); ++i)
    for (double v : step.fields[i])
      if (!std::isfinite(v)) complain(layout.fields[i].name);
}

// The picture of the last finished step, the history CSV and its plot, beside the HDF5 file `h5`.
// Returns the files written, joined for the closing message, and says on stderr what was not drawn.
std::vector<std::string> writeExtras(const std::filesystem::path& h5, const ResultLayout& layout,
                                     const std::vector<StepValues>& recorded, const std::vector<StepScalars>& history,
                                     const ModelDescription& md, const std::string& sceneName) {
  std::vector<std::string> written;
  if (recorded.empty()) return written;
  const std::filesystem::path csv = std::filesystem::path(h5).replace_extension(".csv");
  writeHistoryCsv(csv, layout, history);
  written.push_back(csv.string());
  if (!gnuplotAvailable()) {
    std::cerr << "peristep: gnuplot not on PATH: no pictures\n";
    return written;
  }
  const Variable* input = layout.inputName.empty() ? nullptr : md.find(layout.inputName);
  const std::string inputUnit = input ? input->unit : "";
  std::string scene = sceneName.empty() ? "built-in default scene" : std::filesystem::path(sceneName).filename().string();
  for (const Attribute& a : layout.parameterAttributes)
    if (const auto* name = std::get_if<std::string>(&a.value); name && a.name == "scene") scene += " (" + *name + ")";
  const auto draw = [&](const std::filesystem::path& png, const std::string& problem) {
    if (problem.empty()) written.push_back(png.string());
    else std::cerr << "peristep: no " << png.string() << ": " << problem << '\n';
  };
  const std::filesystem::path picture = std::filesystem::path(h5).replace_extension(".png");
  if (isBarRun(layout, history))  // nothing on the plate grid: the bar's stress-strain path instead
    draw(picture, writeStressStrainPicture(picture, layout, history, md.modelName + ": " + scene));
  else
    draw(picture, writeRunPicture(picture, layout, recorded.back(), {scene, recorded.size(), recorded.size(), inputUnit}));
  std::filesystem::path plot = h5;
  plot.replace_filename(h5.stem().string() + "_history.png");
  draw(plot, plotHistory(plot, layout, history, md.modelName + ": " + scene, inputUnit));
  return written;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return out;
}

}  // namespace

int runCommand(const RunOptions& options) {
  const OpenedFmu fmu(options.fmu);
  const Scene scene = loadScene(options.scene, fmu.md, options.set);
  const std::filesystem::path out = outputPath(options, scene);

  const FmuLibrary library(fmu.archive.binaryFile(fmu.md.coSimulationIdentifier));
  FmuInstance::Options instanceOptions;
  instanceOptions.resourcePath = fmu.archive.resourcePath();
  instanceOptions.verbose = options.verbose;
  // The bar moves inside a step too: the component reports sub-iterations, broken bonds or internal
  // time steps of the step in progress (one load step of a full-size specimen can take minutes).
  ProgressBar* liveBar = nullptr;
  std::uint64_t stepsDone = 0;
  std::vector<std::pair<std::string, std::string>> phases;  // of the step in progress, latest count each
  instanceOptions.progress = [&](const std::string& phase, std::uint64_t done, std::uint64_t total) {
    if (!liveBar) return;
    const std::string count = std::to_string(done) + (total ? "/" + std::to_string(total) : "");
    auto it = std::find_if(phases.begin(), phases.end(), [&](const auto& p) { return p.first == phase; });
    if (it == phases.end()) phases.emplace_back(phase, count);
    else it->second = count;
    std::string note = "step " + std::to_string(stepsDone + 1) + ":";
    for (const auto& [name, value] : phases) note += " " + name + " " + value;
    liveBar->update(stepsDone, note);
  };
  // One writer per output name, decided before the set-up; everything else that can be refused
  // (parameters, initialization) happens before a result file is touched.
  const OutputLock lock(out);
  Simulation simulation(library, fmu.md, scene, instanceOptions);
  const ResultLayout layout = simulation.layout();

  ResultFiles files(out, layout);
  std::vector<StepValues> recorded;
  std::optional<ProgressBar> bar;  // outlives the try: the component may report progress until the last call
  try {
    liveBar = &bar.emplace("run", simulation.schedule().size());
    for (const Increment& inc : simulation.schedule()) {
      if (!simulation.mayContinue()) {
        // Not an error: a fracture scene ends its test this way once the crack has crossed the specimen.
        std::cerr << "peristep: the component ended the run after step " << recorded.size() << " of "
                  << simulation.schedule().size() << " (terminateSimulation: the scene's test is over)\n";
        break;
      }
      StepValues step = simulation.step(inc);
      checkFinite(step, layout, inc.index);
      files.append(step);
      recorded.push_back(std::move(step));
      std::ostringstream note;
      note << "t = " << recorded.back().time;
      stepsDone = inc.index;
      phases.clear();
      bar->update(inc.index, note.str());
    }
    simulation.terminate();
    liveBar = nullptr;
    bar.reset();  // clears the bar before the summary
    files.commit();
  } catch (const RunError& e) {
    const std::filesystem::path kept = files.abandon();
    std::string message = e.what();
    if (kept.empty()) {
      message += "; no results written, " + out.string() + " left as it was";
    } else {
      message += "; the " + std::to_string(recorded.size()) + " finished step(s) are in " + kept.string();
      try {  // the pictures are a courtesy here: failing to draw them must not hide the run's own error
        const auto extras = writeExtras(kept, layout, recorded, files.history(), fmu.md, options.scene);
        if (!extras.empty()) message += " (also " + joined(extras) + ")";
      } catch (const RunError& pictureError) {
        message += std::string(" (no pictures: ") + pictureError.what() + ")";
      }
      message += ", " + out.string() + " left as it was";
    }
    throw RunError(message);
  }
  std::vector<std::string> extras = writeExtras(files.hdf5File(), layout, recorded, files.history(), fmu.md, options.scene);
  extras.insert(extras.begin(), files.xdmfFile().string());

  printSummary(layout, recorded);
  std::cout << "wrote " << files.hdf5File().string() << " (" << recorded.size() << " steps, " << layout.ny << " x "
            << layout.nx << " points), " << joined(extras) << '\n';
  return 0;
}

}  // namespace peristep::host
