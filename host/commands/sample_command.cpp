// `peristep sample SCENE --rule tensor|smolyak|mc (--level L[,L...] | --samples Q[,Q...])`: the scene
// at every point of a rule in the random space the component declares, moments of every output with
// the rule's weights, errors against the exact moments where the component has them, and wall time,
// per level. Finished samples are kept beside the result file, so an interrupted study restarted with
// the same command recomputes none of them.
#include <iostream>

#include "../fmu_loader.hpp"
#include "../host_errors.hpp"
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
  throw InputError("--rule: unknown rule '" + name + "' (tensor, smolyak or mc)");
}

std::string lawText(const RandomSpace& space) {
  if (space.laws.empty()) return "none (Monte Carlo varies the seed: one microstructure per sample)";
  std::string s;
  for (std::size_t d = 0; d < space.laws.size(); ++d)
    s += (d ? ", " : "") + std::string("xi[") + std::to_string(space.index[d]) +
         (space.laws[d] == sampling::Law::Normal ? "] ~ N(0,1)" : "] ~ U[-1,1]");
  return s;
}

void printLevels(const std::vector<LevelResult>& levels, const ResultLayout& layout, bool exact) {
  std::vector<std::string> header{"level", "samples", "computed", "reused"};
  if (exact) header.insert(header.end(), {"error mean", "error std"});
  const bool compared = levels.size() > 1;
  if (compared) header.insert(header.end(), {"to last: mean", "std"});
  header.push_back("wall s");
  // Scalars that vary between the samples of the last level: their moments.
  std::vector<std::size_t> shown;
  for (std::size_t i = 0; i < layout.scalars.size(); ++i) {
    bool varies = false;
    for (const SampleRecord& s : levels.back().records) varies |= s.scalars[i] != levels.back().records[0].scalars[i];
    if (varies) shown.push_back(i), header.push_back("mean " + layout.scalars[i].name), header.push_back("std");
  }
  std::vector<std::vector<std::string>> rows;
  for (const LevelResult& r : levels) {
    std::vector<std::string> row{std::to_string(r.level), std::to_string(r.records.size()), std::to_string(r.computed),
                                 std::to_string(r.reused)};
    if (exact) row.insert(row.end(), {formatNumber(*r.errorMean), formatNumber(*r.errorStd)});
    if (compared)
      row.insert(row.end(), {r.diffMean ? formatNumber(*r.diffMean) : "-", r.diffStd ? formatNumber(*r.diffStd) : "-"});
    row.push_back(formatNumber(r.seconds, 3));
    for (std::size_t i : shown) {
      row.push_back(formatNumber(r.scalarMoments.mean[i]));
      row.push_back(formatNumber(r.scalarMoments.std[i]));
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
                << " output value(s) was negative (negative quadrature weights) and is reported as std = 0\n";
  }
}

}  // namespace

int sampleCommand(const SampleOptions& options) {
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

  const OpenedFmu fmu(options.fmu);
  const Scene scene = loadScene(options.scene, fmu.md);
  std::filesystem::path out = options.out;
  if (out.empty())
    out = std::filesystem::path(options.scene).filename().replace_extension("").string() + "_" + options.rule + ".h5";
  const std::filesystem::path csv = std::filesystem::path(out).replace_extension(".csv");
  const SampleStore store(std::filesystem::path(out).replace_extension(".samples"));

  const std::filesystem::path binary = fmu.archive.binaryFile(fmu.md.coSimulationIdentifier);
  const FmuLibrary library(binary);
  FmuInstance::Options instanceOptions;
  instanceOptions.resourcePath = fmu.archive.resourcePath();
  instanceOptions.verbose = options.verbose;
  const RandomSpace space = readRandomSpace(library, fmu.md, scene, instanceOptions);
  std::cout << "# " << options.scene << ": random coordinates " << lawText(space) << "; rule " << options.rule
            << (rule.rule == SampleRule::Smolyak ? (options.nested ? " (nested)" : " (Gauss)") : "") << '\n';

  SampleStudy study(library, fmu.md, scene, instanceOptions, store, SampleStore::fileDigest(binary));
  StudyDescription description{options.scene, options.rule,
                               {{"nested", std::vector<std::int64_t>{options.nested}},
                                {"seed", std::vector<std::uint64_t>{options.seed}},
                                {"sampleDirectory", store.directory().string()}}};
  std::vector<LevelResult> levels;
  for (std::uint64_t level : rule.levels) {
    ProgressBar bar("level " + std::to_string(level), 1);
    LevelResult r = study.runLevel(rule, space, level, [&](std::size_t done, std::size_t total) {
      bar.update(0, std::to_string(done) + "/" + std::to_string(total) + " samples");
    });
    levels.push_back(std::move(r));
    writeStudyHdf5(out, description, study.layout(), levels);  // finished levels are on disk at once
    writeStudyCsv(csv, study.layout(), levels);
  }
  compareWithLast(levels, study.layout());
  writeStudyHdf5(out, description, study.layout(), levels);
  writeStudyCsv(csv, study.layout(), levels);
  printLevels(levels, study.layout(), study.hasExactMoments());
  std::cout << plotSampleStudy(csv, fmu.md.modelName + ": " + options.scene + ", rule " + options.rule) << '\n';
  std::cout << "wrote " << out.string() << " and " << csv.string() << " (samples kept in " << store.directory().string()
            << ")\n";
  return 0;
}

}  // namespace peristep::host
