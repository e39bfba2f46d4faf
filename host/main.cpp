// peristep: runs the PeriStep FMU through its C ABI only (see commands/ for what each subcommand does).
#include <CLI/CLI.hpp>

#include <iostream>
#include <utility>

#include "commands/commands.hpp"
#include "host_errors.hpp"
#include "process_settings.hpp"

using namespace peristep::host;

int main(int argc, char** argv) {
  peristep::startWithProcessSettings(argv);  // before the FMU (and with it libgomp and OpenBLAS) is loaded
  CLI::App app{"peristep: drive the PeriStep peridynamic fracture component (an FMI 3.0 co-simulation FMU)"};
  app.set_version_flag("--version", PERISTEP_VERSION);
  app.require_subcommand(1);

  InfoOptions info;
  RunOptions run;
  ConvergenceOptions convergence;
  SampleOptions sample;
  info.fmu = run.fmu = convergence.fmu = sample.fmu = PERISTEP_DEFAULT_FMU;
  const std::string fmuHelp = "FMU archive (.fmu) or unpacked FMU directory";

  unsigned threads = 0;
  app.add_option("--threads", threads, "OpenMP threads of the component; default: OMP_NUM_THREADS, else all cores")
      ->check(CLI::Range(1u, 4096u));
  app.fallthrough();  // --threads after the subcommand too

  CLI::App* infoCmd = app.add_subcommand("info", "the scenes and variables a scene file can name, one line each");
  infoCmd->add_option("name", info.name, "a variable or scene to show in full");
  infoCmd->add_option("--fmu", info.fmu, fmuHelp)->capture_default_str();
  const std::string setHelp = "set a [parameters] value of the scene (repeatable), e.g. --set nx=101";

  CLI::App* runCmd = app.add_subcommand("run", "run a loading scenario; results to HDF5 with an XDMF sidecar");
  runCmd->add_option("scene", run.scene, "scene file (TOML); without one, the built-in default scene");
  runCmd->add_option("--fmu", run.fmu, fmuHelp)->capture_default_str();
  runCmd->add_option("--out", run.out, "HDF5 result file (default: the scene's [output] file)");
  runCmd->add_option("--set", run.set, setHelp)->allow_extra_args(false);
  runCmd->add_flag("-v,--verbose", run.verbose, "echo every message the component logs");

  CLI::App* convCmd = app.add_subcommand("convergence", "refinement study over the scene's [convergence] levels");
  convCmd->add_option("scene", convergence.scene, "scene file (TOML) with [convergence] levels")->required();
  convCmd->add_option("--fmu", convergence.fmu, fmuHelp)->capture_default_str();
  convCmd->add_option("--out", convergence.out, "CSV table (default: the scene's [output] csv); plot beside it");
  convCmd->add_option("--set", convergence.set, setHelp)->allow_extra_args(false);
  convCmd->add_flag("-v,--verbose", convergence.verbose, "echo every message the component logs");

  CLI::App* sampleCmd =
      app.add_subcommand("sample", "statistics over the random coordinates: tensor or Smolyak collocation, Monte Carlo, "
                        "multilevel Monte Carlo over grids");
  sampleCmd->add_option("scene", sample.scene, "scene file (TOML)")->required();
  sampleCmd->add_option("--rule", sample.rule, "tensor, smolyak, mc or mlmc")->required();
  sampleCmd->add_option("--level,--levels", sample.levels,
                        "tensor: points per coordinate; smolyak: level (0 = one point); a list runs a study")
      ->delimiter(',');
  sampleCmd->add_option("--samples", sample.samples, "mc: number of samples; a list runs a study")->delimiter(',');
  sampleCmd->add_flag("--nested", sample.nested, "smolyak: nested 1D rules instead of Gauss rules");
  sampleCmd->add_option("--seed", sample.seed, "mc: seed (or the first seed of a scene without random coordinates: microstructure, bar realization)")->capture_default_str();
  sampleCmd->add_option("--fmu", sample.fmu, fmuHelp)->capture_default_str();
  sampleCmd->add_option("--out", sample.out, "HDF5 study file (default: <scene>_<rule>.h5); CSV beside it");
  sampleCmd->add_option("--set", sample.set, setHelp)->allow_extra_args(false);
  sampleCmd->add_flag("-v,--verbose", sample.verbose, "echo every message the component logs");
  sampleCmd->add_option("--shard", sample.shard,
                        "K/N: run only samples K, K+N, K+2N, ... (1 <= K <= N) of every level and store them; "
                        "no statistics (for batch arrays without MPI)");
  sampleCmd->add_option("--grids", sample.grids,
                        "mlmc: number of grids; the scene's is the finest, each coarser halves nx - 1 and ny - 1")
      ->capture_default_str();
  sampleCmd->add_option("--quantity", sample.quantity,
                        "mlmc: the scalar output estimated (default: the scene's first [output] result, else toughnessKIC)");
  sampleCmd->add_option("--se", sample.se, "mlmc: target standard error relative to the estimate")->capture_default_str();
  sampleCmd->add_option("--se-absolute", sample.seAbsolute, "mlmc: target standard error in the quantity's unit");
  sampleCmd->add_option("--pilot", sample.pilot, "mlmc: samples per level before the counts are chosen")
      ->capture_default_str();
  sampleCmd->add_option("--level-costs", sample.levelCosts,
                        "mlmc: cost per sample of each level for the allocation (default: the measured wall times)")
      ->delimiter(',');
  sampleCmd->add_flag("--merge", sample.merge,
                      "run no sample: statistics and result files from the stored samples (after --shard runs)")
      ->excludes("--shard");

  for (CLI::App* command : {runCmd, convCmd, sampleCmd})
    command->footer("--threads N (here or before the subcommand): threads of the component");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);  // --help, --version
    std::cerr << "peristep: " << e.what() << " (see peristep --help)\n";
    return kExitInputError;
  }

  // Before the FMU, and with it libgomp, is loaded: it reads the count when loaded.
  if (threads > 0) peristep::setThreadCount(threads);
  if (sampleCmd->parsed()) peristep::preferSerialBlas();
  // `peristep info FMU`, as before --fmu existed: a name that is an FMU path is the FMU.
  if (info.name.size() > 4 && info.name.ends_with(".fmu")) info.fmu = std::exchange(info.name, "");

  try {
    if (infoCmd->parsed()) return infoCommand(info);
    if (runCmd->parsed()) return runCommand(run);
    if (sampleCmd->parsed()) return sampleCommand(sample);
    return convergenceCommand(convergence);
  } catch (const InputError& e) {
    std::cerr << "peristep: " << e.what() << '\n';
    return kExitInputError;
  } catch (const std::exception& e) {
    std::cerr << "peristep: " << e.what() << '\n';
    return kExitRunError;
  }
}
