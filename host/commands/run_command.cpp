// `peristep run [SCENE] [--fmu PATH] [--out FILE]`: one loading scenario, results to HDF5 + XDMF.
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>

#include "../damage_picture.hpp"
#include "../fmu_loader.hpp"
#include "../host_errors.hpp"
#include "../progress.hpp"
#include "../result_files.hpp"
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

// The damage picture of the last finished step, next to the HDF5 file `h5`; nothing when no step
// finished or the model lacks the fields it is drawn from.
std::optional<std::filesystem::path> writePicture(const std::filesystem::path& h5, const ResultLayout& layout,
                                                  const std::vector<StepValues>& recorded) {
  if (recorded.empty()) return std::nullopt;
  return writeDamagePicture(std::filesystem::path(h5).replace_extension(".png"), layout, recorded.back());
}

}  // namespace

int runCommand(const RunOptions& options) {
  const OpenedFmu fmu(options.fmu);
  const Scene scene = loadScene(options.scene, fmu.md);
  const std::filesystem::path out = outputPath(options, scene);

  const FmuLibrary library(fmu.archive.binaryFile(fmu.md.coSimulationIdentifier));
  FmuInstance::Options instanceOptions;
  instanceOptions.resourcePath = fmu.archive.resourcePath();
  instanceOptions.verbose = options.verbose;
  // Everything that can be refused (parameters, initialization) happens before a file is touched.
  Simulation simulation(library, fmu.md, scene, instanceOptions);
  const ResultLayout layout = simulation.layout();

  ResultFiles files(out, layout);
  std::vector<StepValues> recorded;
  try {
    ProgressBar bar("run", simulation.schedule().size());
    for (const Increment& inc : simulation.schedule()) {
      if (!simulation.mayContinue()) {
        std::cerr << "peristep: the component asked to stop after step " << recorded.size() << '\n';
        break;
      }
      StepValues step = simulation.step(inc);
      checkFinite(step, layout, inc.index);
      files.append(step);
      recorded.push_back(std::move(step));
      std::ostringstream note;
      note << "t = " << recorded.back().time;
      bar.update(inc.index, note.str());
    }
    simulation.terminate();
    files.commit();
  } catch (const RunError& e) {
    const std::filesystem::path kept = files.abandon();
    std::string message = e.what();
    if (kept.empty()) {
      message += "; no results written, " + out.string() + " left as it was";
    } else {
      message += "; the " + std::to_string(recorded.size()) + " finished step(s) are in " + kept.string();
      try {  // the picture is a courtesy here: failing to draw it must not hide the run's own error
        if (const auto png = writePicture(kept, layout, recorded)) message += " (picture " + png->string() + ")";
      } catch (const RunError& pictureError) {
        message += std::string(" (no picture: ") + pictureError.what() + ")";
      }
      message += ", " + out.string() + " left as it was";
    }
    throw RunError(message);
  }
  const auto png = writePicture(files.hdf5File(), layout, recorded);

  printSummary(layout, recorded);
  std::cout << "wrote " << files.hdf5File().string() << " (" << recorded.size() << " steps, " << layout.ny << " x "
            << layout.nx << " points)" << (png ? ", " : " and ") << files.xdmfFile().string();
  if (png) std::cout << " and " << png->string();
  std::cout << '\n';
  return 0;
}

}  // namespace peristep::host
