// `peristep sample SCENE --rule tensor|smolyak|mc (--level L[,L...] | --samples Q[,Q...])`: the scene
// at every point of a rule in the random space the component declares, moments of every output with
// the rule's weights, errors against the exact moments where the component has them, and wall time,
// per level, to HDF5 with an XDMF file for the field statistics, a CSV table and a plot (with the
// distribution of the study's results, e.g. K_IC). Finished samples are kept beside the result file,
// so an interrupted study restarted with the same command recomputes none of them.
// Under mpirun the ranks share each level's samples (dynamic scheduling, mpi_work_queue.hpp) and rank 0
// writes the results; --shard K/N runs a fixed part for batch arrays, --merge the statistics afterwards.
#include <cmath>
#include <iostream>
#include <optional>
#include <utility>

#include "../fmu_loader.hpp"
#include "../host_errors.hpp"
#include "../mpi_session.hpp"
#include "../mpi_work_queue.hpp"
#include "../multilevel_study.hpp"
#include "../output_lock.hpp"
#include "../progress.hpp"
#include "../sample_plot.hpp"
#include "../sample_results.hpp"
#include "../sample_study.hpp"
#include "commands.hpp"
#include "opened_fmu.hpp"

namespace peristep::host {

namespace {

SampleRule parseRule(const std::string& name) {
  if (name == "tensor") return SampleRule::Tensor;
  if (name == "smolyak") return SampleRule::Smolyak;
  if (name == "mc") return SampleRule::MonteCarlo;
  throw InputError("--rule: unknown rule '" + name + "' (tensor, smolyak, mc or mlmc)");
}

std::string lawText(const RandomSpace& space) {
  if (space.laws.empty()) return "none (Monte Carlo varies the seed: one realization per sample, e.g. a microstructure)";
  std::string s;
  for (std::size_t d = 0; d < space.laws.size(); ++d)
    s += (d ? ", " : "") + std::string("xi[") + std::to_string(space.index[d]) +
         (space.laws[d] == sampling::Law::Normal ? "] ~ N(0,1)" : "] ~ U[-1,1]");
  return s;
}

struct Shard {
  std::size_t index = 0, count = 1;  // runs the jobs k with k % count == index (default: all)
};

Shard parseShard(const std::string& text) {
  Shard shard;
  const std::size_t slash = text.find('/');
  try {
    std::size_t used = 0;
    const unsigned long k = std::stoul(text.substr(0, slash), &used);
    const unsigned long n = std::stoul(text.substr(slash + 1));
    if (slash == std::string::npos || used != slash || k < 1 || k > n) throw std::invalid_argument(text);
    shard = {k - 1, n};
  } catch (const std::logic_error&) {
    throw InputError("--shard: expected K/N with 1 <= K <= N, got '" + text + "'");
  }
  return shard;
}

void printLevels(const std::vector<LevelResult>& levels, const ResultLayout& layout, bool exact, SampleRule rule) {
  std::vector<std::string> header{"level", "samples", "computed", "reused", "failed"};
  if (exact) header.insert(header.end(), {"error mean", "error std"});
  const bool compared = levels.size() > 1;
  if (compared) header.insert(header.end(), {"to last: mean", "std"});
  header.push_back("wall s");
  // Scalars that vary between the samples of the last level: their moments. Which standard deviation
  // a column holds is in its header: "std" with the rule's weights 000:(3.11), "PCE std" of the sparse
  // pseudo-spectral surrogate, "+-se" the Monte Carlo standard errors.
  std::vector<std::size_t> shown;
  for (std::size_t i = 0; i < layout.scalars.size(); ++i) {
    bool varies = false;  // among the successful samples (a failed one holds NaN)
    std::optional<double> first;
    for (const SampleRecord& s : levels.back().records)
      if (!std::isnan(s.scalars[i])) varies |= first.value_or(s.scalars[i]) != s.scalars[i], first = s.scalars[i];
    if (!varies) continue;
    shown.push_back(i);
    header.push_back("mean " + layout.scalars[i].name);
    if (rule == SampleRule::MonteCarlo) header.push_back("+-se");
    header.push_back(rule == SampleRule::Smolyak ? "std (quadrature)" : "std");
    if (rule == SampleRule::MonteCarlo) header.push_back("+-se");
    if (rule == SampleRule::Smolyak) header.push_back("PCE std");
  }
  std::vector<std::vector<std::string>> rows;
  for (const LevelResult& r : levels) {
    std::vector<std::string> row{std::to_string(r.level), std::to_string(r.records.size()), std::to_string(r.computed),
                                 std::to_string(r.reused), std::to_string(r.failures.size())};
    const auto opt = [](const std::optional<double>& v) { return v ? formatNumber(*v) : std::string("-"); };
    if (exact) row.insert(row.end(), {opt(r.errorMean), opt(r.errorStd)});
    if (compared) row.insert(row.end(), {opt(r.diffMean), opt(r.diffStd)});
    row.push_back(formatNumber(r.seconds, 3));
    const Moments& m = r.scalarMoments;
    for (std::size_t i : shown) {
      row.push_back(formatNumber(m.mean[i]));
      if (!m.seMean.empty()) row.push_back(formatNumber(m.seMean[i]));
      row.push_back(formatNumber(m.std[i]));
      if (!m.seStd.empty()) row.push_back(formatNumber(m.seStd[i]));
      if (!m.pceStd.empty()) row.push_back(formatNumber(m.pceStd[i]));
    }
    rows.push_back(row);
  }
  printTable(std::cout, header, rows);
  // Sparse-grid weights can be negative (level 1 in 20 dimensions: -5.67 on the centre node): for an output
  // that is not smooth in xi the variance estimate can come out negative. Say so instead of hiding it.
  for (const LevelResult& r : levels) {
    std::size_t clamped = r.scalarMoments.clamped;
    for (const Moments& m : r.fieldMoments) clamped += m.clamped;
    if (clamped > 0)
      std::cout << "level " << r.level << ": the variance estimate of " << clamped
                << " output value(s) was negative (negative quadrature weights) and is reported as std = 0"
                << (rule == SampleRule::Smolyak ? "; the PCE std is a sum of squares and cannot be negative" : "")
                << '\n';
  }
  if (rule == SampleRule::MonteCarlo)
    std::cout << "Monte Carlo: se(mean) = s/sqrt(Q); se(std) = se(variance)/(2 std), se(variance) = sqrt((m4 - "
                 "m2^2)/Q); 95% interval of the mean: mean -+ 1.96 se(mean)\n";
}

// Failed samples: how many, which, and what the statistics of their level are.
std::size_t printFailures(const std::vector<LevelResult>& levels, SampleRule rule) {
  std::size_t total = 0;
  for (const LevelResult& r : levels) {
    if (r.failures.empty()) continue;
    total += r.failures.size();
    std::cout << "level " << r.level << ": " << r.failures.size() << " of " << r.records.size()
              << " samples failed; "
              << (rule == SampleRule::MonteCarlo
                      ? "the moments are over the " + std::to_string(r.records.size() - r.failures.size()) +
                            " successful samples (equal weights: the law given success, biased if failing "
                            "depends on the output)"
                      : std::string("no moments: the rule's weights do not allow dropping a node (NaN in the files)"))
              << '\n';
    for (const SampleFailure& f : r.failures) std::cout << "  " << f.message << '\n';
  }
  if (total > 0)
    std::cout << "A failed sample is finished as well: a restart does not retry it unless its .failed file in the "
                 "sample directory is deleted.\n";
  return total;
}

// The results the study is about, over the last level's successful samples: the scalars the scene names
// in [output] results, else the fracture toughness where the samples computed one.
std::vector<ResultDistribution> resultDistributions(const Scene& scene, const ResultLayout& layout, const LevelResult& last) {
  std::vector<std::string> names = scene.results;
  if (names.empty()) names = {"toughnessKIC"};
  std::vector<ResultDistribution> out;
  for (const std::string& name : names)
    for (std::size_t i = 0; i < layout.scalars.size(); ++i) {
      if (layout.scalars[i].name != name) continue;
      ResultDistribution r{name, layout.scalars[i].unit, {}, NAN, NAN, NAN, NAN, ""};
      bool computed = !scene.results.empty();  // a named result is drawn even where it is zero
      for (const SampleRecord& s : last.records)
        if (std::isfinite(s.scalars[i])) r.values.push_back(s.scalars[i]), computed |= s.scalars[i] != 0;
      if (!computed || r.values.empty() || !last.momentsComputed) continue;
      const Moments& m = last.scalarMoments;
      r.mean = m.mean[i];
      r.std = m.std[i];
      if (!m.seMean.empty() && std::isfinite(m.seMean[i])) {
        r.low = r.mean - interval95(m.seMean[i]), r.high = r.mean + interval95(m.seMean[i]);
        r.interval = "95% interval of the mean";
      } else if (m.seMean.empty()) {
        r.low = r.mean - m.std[i], r.high = r.mean + m.std[i];
        r.interval = "mean -+ std";
      }
      out.push_back(std::move(r));
    }
  return out;
}

// What every rule opens before its first sample: the FMU and its library, the scene, the output's lock
// (taken by the process that writes the results, before the sample store is opened), the store beside
// the output, and the random space the component declares.
struct StudySetup {
  StudySetup(const SampleOptions& options, bool writes)
      : fmu(options.fmu),
        scene(loadScene(options.scene, fmu.md, options.set)),
        out(options.out.empty() ? std::filesystem::path(std::filesystem::path(options.scene).filename().replace_extension("").string() +
                                                        "_" + options.rule + ".h5")
                                : std::filesystem::path(options.out)),
        lock(writes ? std::optional<OutputLock>(std::in_place, out) : std::nullopt),
        store(std::filesystem::path(out).replace_extension(".samples")),
        binary(fmu.archive.binaryFile(fmu.md.coSimulationIdentifier)),
        library(binary) {
    instance.resourcePath = fmu.archive.resourcePath();
    instance.verbose = options.verbose;
    space = readRandomSpace(library, fmu.md, scene, instance);
  }

  const OpenedFmu fmu;
  const Scene scene;
  const std::filesystem::path out;
  const std::optional<OutputLock> lock;
  const SampleStore store;
  const std::filesystem::path binary;
  const FmuLibrary library;
  FmuInstance::Options instance;
  RandomSpace space;
};

// --rule mlmc: multilevel Monte Carlo of one scalar output over grids (multilevel_study.hpp).
int runMultilevelStudy(const SampleOptions& options, const MpiSession& mpi) {
  if (!options.shard.empty() || options.merge || !options.levels.empty() || !options.samples.empty() || options.nested)
    throw InputError("--rule mlmc chooses its own sample counts: it takes --grids, --quantity, --se, --se-absolute, "
                     "--pilot, --level-costs and --seed");
  const StudySetup setup(options, mpi.rank() == 0);
  MultilevelOptions ml;
  ml.grids = options.grids;
  ml.quantity = options.quantity;
  if (ml.quantity.empty()) ml.quantity = setup.scene.results.empty() ? "toughnessKIC" : setup.scene.results.front();
  ml.relativeSe = options.se;
  ml.absoluteSe = options.seAbsolute;
  ml.pilot = options.pilot;
  ml.seed = options.seed;
  ml.costs = options.levelCosts;
  if (mpi.rank() == 0)
    std::cout << "# " << options.scene << ": random coordinates " << lawText(setup.space) << "; rule mlmc over "
              << ml.grids << " grids of " << ml.quantity
              << (mpi.size() > 1 ? "; " + std::to_string(mpi.size()) + " MPI ranks" : "") << '\n';
  const MultilevelResult result = runMultilevel(setup.library, setup.fmu.md, setup.scene, setup.instance, setup.store,
                                                SampleStore::fileDigest(setup.binary), setup.space, ml, mpi);
  if (mpi.rank() != 0) return 0;
  const std::filesystem::path csv = std::filesystem::path(setup.out).replace_extension(".csv");
  const std::filesystem::path summary =
      std::filesystem::path(setup.out).replace_extension("").string() + "_summary.csv";
  writeMultilevelCsv(csv, summary, result);
  printMultilevel(std::cout, result);
  std::cout << "wrote " << csv.string() << " and " << summary.string() << " (samples kept in "
            << setup.store.directory().string() << ")\n";
  std::size_t failed = 0;
  for (const MultilevelLevel& l : result.levels) failed += l.failures.size();
  return failed > 0 ? kExitRunError : 0;
}

int runStudy(const SampleOptions& options, const MpiSession& mpi) {
  if (options.rule == "mlmc") return runMultilevelStudy(options, mpi);
  SamplingOptions rule;
  rule.rule = parseRule(options.rule);
  rule.nested = options.nested;
  rule.seed = options.seed;
  rule.levels = rule.rule == SampleRule::MonteCarlo ? options.samples : options.levels;
  if (rule.levels.empty())
    throw InputError(rule.rule == SampleRule::MonteCarlo ? "--rule mc needs --samples Q (or Q1,Q2,...)"
                                                         : "--rule " + options.rule + " needs --level L (or L1,L2,...)");
  if (rule.rule == SampleRule::MonteCarlo && !options.levels.empty())
    throw InputError("--rule mc takes --samples, not --level");
  if (rule.rule != SampleRule::MonteCarlo && !options.samples.empty())
    throw InputError("--rule " + options.rule + " takes --level, not --samples");
  const bool sharded = !options.shard.empty();
  const Shard shard = sharded ? parseShard(options.shard) : Shard{};
  if ((sharded || options.merge) && mpi.size() > 1)
    throw InputError("--shard and --merge are for runs without MPI; under mpirun the ranks share the samples");
  const bool root = mpi.rank() == 0, writes = root && !sharded;

  const StudySetup setup(options, writes);
  const OpenedFmu& fmu = setup.fmu;
  const Scene& scene = setup.scene;
  const std::filesystem::path& out = setup.out;
  const std::filesystem::path csv = std::filesystem::path(out).replace_extension(".csv");
  const SampleStore& store = setup.store;
  const RandomSpace& space = setup.space;
  if (root)
    std::cout << "# " << options.scene << ": random coordinates " << lawText(space) << "; rule " << options.rule
              << (rule.rule == SampleRule::Smolyak ? (options.nested ? " (nested)" : " (Gauss)") : "")
              << (mpi.size() > 1 ? "; " + std::to_string(mpi.size()) + " MPI ranks" : "")
              << (sharded ? "; shard " + options.shard : "") << (options.merge ? "; merging stored samples" : "") << '\n';

  SampleStudy study(setup.library, fmu.md, scene, setup.instance, store, SampleStore::fileDigest(setup.binary));
  StudyDescription description{options.scene, options.rule,
                               {{"nested", std::vector<std::int64_t>{options.nested}},
                                {"seed", std::vector<std::uint64_t>{options.seed}},
                                {"sampleDirectory", store.directory().string()}}};
  if (!options.set.empty()) {  // the study's parameters differ from the scene file's: say how
    std::string set;
    for (const std::string& s : options.set) set += (set.empty() ? "" : " ") + s;
    description.attributes.push_back({"set", set});
  }
  std::vector<LevelResult> levels;
  LevelWork shardWork;
  for (std::uint64_t level : rule.levels) {
    ProgressBar bar("level " + std::to_string(level), 1);  // drawn on a terminal only; times the level
    LevelPlan plan = planLevel(rule, space, level);
    LevelWork work;
    if (!options.merge) {
      const auto progress = [&](std::size_t index, std::size_t total) {
        if (root) bar.update(0, "sample " + std::to_string(index) + "/" + std::to_string(total));
      };
      if (mpi.size() > 1) {
        MpiWorkQueue queue(mpi, plan.jobs.size());
        work = study.runJobs(plan, [&] { return queue.next(); }, progress);
        queue.finish();
        work = {mpi.sumToRoot(work.computed), mpi.sumToRoot(work.reused), mpi.sumToRoot(work.failed)};
      } else {
        std::size_t next = shard.index;
        work = study.runJobs(plan, [&]() -> std::optional<std::size_t> {
          if (next >= plan.jobs.size()) return std::nullopt;
          return std::exchange(next, next + shard.count);
        }, progress);
      }
    }
    shardWork = {shardWork.computed + work.computed, shardWork.reused + work.reused, shardWork.failed + work.failed};
    if (!writes) continue;
    LevelResult r = study.collect(std::move(plan), rule.rule, level);
    r.computed = work.computed;
    r.reused = r.records.size() - work.computed;
    r.seconds = bar.elapsedSeconds();
    levels.push_back(std::move(r));
    writeStudyHdf5(out, description, study.layout(), levels);  // finished levels are on disk at once
    writeStudyXdmfFile(std::filesystem::path(out).replace_extension(".xmf"), out, study.layout(), levels);
    writeStudyCsv(csv, study.layout(), levels);
  }
  if (sharded) {
    std::cout << "shard " << options.shard << ": computed " << shardWork.computed << " samples (" << shardWork.failed
              << " failed), found " << shardWork.reused << " in " << store.directory().string()
              << "; statistics: the same command with --merge instead of --shard once all shards are done\n";
    return 0;
  }
  if (!root) return 0;
  compareWithLast(levels, study.layout());
  writeStudyHdf5(out, description, study.layout(), levels);
  writeStudyCsv(csv, study.layout(), levels);
  const std::filesystem::path xmf = std::filesystem::path(out).replace_extension(".xmf");
  writeStudyXdmfFile(xmf, out, study.layout(), levels);
  printLevels(levels, study.layout(), study.hasExactMoments(), rule.rule);
  const std::size_t failed = printFailures(levels, rule.rule);
  const std::string sceneName = std::filesystem::path(options.scene).filename().string();
  std::cout << plotSampleStudy(csv, fmu.md.modelName + ": " + sceneName + ", rule " + options.rule,
                               resultDistributions(scene, study.layout(), levels.back()))
            << '\n';
  std::cout << "wrote " << out.string() << ", " << xmf.string() << " and " << csv.string() << " (samples kept in "
            << store.directory().string() << ")\n";
  return failed > 0 ? kExitRunError : 0;
}

}  // namespace

int sampleCommand(const SampleOptions& options) {
  const MpiSession mpi;
  try {
    return runStudy(options, mpi);
  } catch (const std::exception& e) {
    // One rank's error would leave the others waiting for it: end them all, with this rank's message.
    if (mpi.size() > 1) mpi.abort(e.what(), dynamic_cast<const InputError*>(&e) ? kExitInputError : kExitRunError);
    throw;
  }
}

}  // namespace peristep::host
