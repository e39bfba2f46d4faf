#include "multilevel_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <thread>

#include "atomic_file.hpp"
#include "host_errors.hpp"
#include "mpi_work_queue.hpp"
#include "progress.hpp"

namespace peristep::host {

namespace {

std::uint64_t gridSize(const Scene& scene, const ModelDescription& md, const char* name) {
  if (const Setting* s = scene.setting(name))
    if (const auto* v = std::get_if<std::vector<std::uint64_t>>(&s->values); v && v->size() == 1) return v->front();
  const Variable& v = gridVariable(md, name, "coarsen");
  if (!v.start) throw InputError("--rule mlmc: " + md.modelName + " gives " + name + " no start value to coarsen");
  return std::stoull(*v.start);
}

// Q of one grid at the jobs of a level's plan so far, with the wall times and refusals: grown by the new
// jobs of each round (a Monte Carlo plan of more samples starts with those of fewer).
struct GridValues {
  std::vector<double> values, seconds;
  std::map<std::size_t, std::string> failed;  // job index -> the component's message
};

std::size_t quantityIndex(const ResultLayout& layout, const std::string& quantity) {
  const auto& scalars = layout.scalars;
  const auto it = std::find_if(scalars.begin(), scalars.end(), [&](const ArrayInfo& a) { return a.name == quantity; });
  if (it == scalars.end()) {
    std::string names;
    for (const ArrayInfo& a : scalars) names += (names.empty() ? "" : ", ") + a.name;
    throw InputError("--quantity: '" + quantity + "' is not a scalar Float64 output of this scene (" + names + ")");
  }
  return static_cast<std::size_t>(it - scalars.begin());
}

// Adds the plan's jobs that `g` does not hold yet: Q only, read from the store without the fields.
void collectNew(SampleStudy& study, const LevelPlan& plan, std::size_t level, const std::string& quantity, GridValues& g) {
  const std::size_t first = g.values.size();
  if (first >= plan.jobs.size()) return;
  ScalarSamples s = study.collectScalar(plan, level, quantityIndex(study.layout(), quantity), first);
  g.values.insert(g.values.end(), s.values.begin(), s.values.end());
  g.seconds.insert(g.seconds.end(), s.seconds.begin(), s.seconds.end());
  g.failed.merge(s.failures);
}

double meanOf(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

std::string threadsPerSample() {
  if (const char* t = std::getenv("OMP_NUM_THREADS"); t && *t) return t;
  return std::to_string(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace

Scene sceneOnGrid(const Scene& scene, const ModelDescription& md, std::size_t grids, std::size_t level,
                  std::uint64_t& nx, std::uint64_t& ny) {
  const std::uint64_t factor = std::uint64_t{1} << (grids - 1 - level);
  for (const char* name : {"nx", "ny"}) {
    const std::uint64_t n = gridSize(scene, md, name);
    if (n < 2 || (n - 1) % factor != 0 || (n - 1) / factor < 1)
      throw InputError("--rule mlmc --grids " + std::to_string(grids) + ": " + name + " - 1 = " + std::to_string(n - 1) +
                       " must be a multiple of " + std::to_string(factor) + " (each coarser grid halves it)");
    (name[1] == 'x' ? nx : ny) = (n - 1) / factor + 1;
  }
  return sceneWithGrid(scene, md, nx, ny, "coarsen");
}

MultilevelResult runMultilevel(const FmuLibrary& library, const ModelDescription& md, const Scene& scene,
                               const FmuInstance::Options& instance, const SampleStore& store,
                               const std::string& componentId, const RandomSpace& space,
                               const MultilevelOptions& options, const MpiSession& mpi) {
  const std::size_t L = options.grids;
  if (L < 1 || L > 8) throw InputError("--grids: between 1 and 8 grids");
  if (options.pilot < 2) throw InputError("--pilot: at least 2 samples per level (a variance needs two)");
  if (!options.costs.empty() && options.costs.size() != L)
    throw InputError("--level-costs: one cost per grid (" + std::to_string(L) + ")");
  for (double c : options.costs)
    if (!(c > 0) || !std::isfinite(c)) throw InputError("--level-costs: costs must be positive");
  if (!(options.absoluteSe > 0) && !(options.relativeSe > 0 && options.relativeSe < 1))
    throw InputError("--se: give a relative standard error in (0, 1) or --se-absolute > 0");

  MultilevelResult r;
  r.quantity = options.quantity;
  std::vector<Scene> grids(L);
  std::vector<std::uint64_t> nx(L), ny(L);
  for (std::size_t g = 0; g < L; ++g) grids[g] = sceneOnGrid(scene, md, L, g, nx[g], ny[g]);
  std::vector<std::unique_ptr<SampleStudy>> studies;
  for (const Scene& s : grids) studies.push_back(std::make_unique<SampleStudy>(library, md, s, instance, store, componentId));

  const auto planOf = [&](std::size_t level, std::uint64_t count) {
    SamplingOptions mc;
    mc.rule = SampleRule::MonteCarlo;
    mc.seed = options.seed + level * kMaxPlannedSamples;  // disjoint seeds: independent levels
    return planLevel(mc, space, count);
  };
  const auto run = [&](std::size_t grid, const LevelPlan& plan, const std::string& label) {
    ProgressBar bar(label, 1);
    const auto progress = [&](std::size_t index, std::size_t total) {
      if (mpi.rank() == 0) bar.update(0, "sample " + std::to_string(index) + "/" + std::to_string(total));
    };
    if (mpi.size() > 1) {
      MpiWorkQueue queue(mpi, plan.jobs.size());
      const LevelWork work = studies[grid]->runJobs(plan, [&] { return queue.next(); }, progress);
      queue.finish();
      r.computed += mpi.sumToRoot(work.computed);
    } else {
      std::size_t next = 0;
      r.computed += studies[grid]->runJobs(plan, [&]() -> std::optional<std::size_t> {
        if (next >= plan.jobs.size()) return std::nullopt;
        return next++;
      }, progress).computed;
    }
  };

  std::vector<std::uint64_t> counts(L, options.pilot);
  // Level l: Q on grid l and (l > 0) on grid l - 1 at the jobs of level l's plan, collected so far.
  std::vector<GridValues> fineValues(L), coarseValues(L);
  for (r.rounds = 1;; ++r.rounds) {
    std::vector<LevelPlan> plans;
    for (std::size_t l = 0; l < L; ++l) {
      plans.push_back(planOf(l, counts[l]));
      const std::string grid = std::to_string(nx[l]) + "x" + std::to_string(ny[l]);
      run(l, plans[l], "level " + std::to_string(l) + " on " + grid);
      if (l > 0) run(l - 1, plans[l], "level " + std::to_string(l) + " on " + std::to_string(nx[l - 1]) + "x" + std::to_string(ny[l - 1]));
    }
    std::vector<std::uint64_t> next;
    if (mpi.rank() == 0) {
      r.levels.assign(L, {});
      const ResultLayout& layout = studies.back()->layout();
      r.unit = layout.scalars[quantityIndex(layout, options.quantity)].unit;
      std::vector<sampling::LevelStatistics> stats;
      std::vector<double> variance, cost;
      for (std::size_t l = 0; l < L; ++l) {
        MultilevelLevel& level = r.levels[l];
        level.nx = nx[l], level.ny = ny[l], level.planned = counts[l];
        collectNew(*studies[l], plans[l], l, options.quantity, fineValues[l]);
        if (l > 0) collectNew(*studies[l - 1], plans[l], l, options.quantity, coarseValues[l]);
        const GridValues& fine = fineValues[l];
        const GridValues& coarse = coarseValues[l];
        std::vector<double> diff, fineSeconds, coarseSeconds;
        for (std::size_t k = 0; k < counts[l]; ++k) {
          const auto failedFine = fine.failed.find(k);
          const auto failedCoarse = l > 0 ? coarse.failed.find(k) : coarse.failed.end();
          if (failedFine != fine.failed.end() || failedCoarse != coarse.failed.end()) {
            const std::string& why = failedFine != fine.failed.end() ? failedFine->second : failedCoarse->second;
            level.failures.push_back({k, "level " + std::to_string(l) + ": " + describeJob(plans[l], k) + ": " + why});
            continue;
          }
          level.fine.push_back(fine.values[k]);
          fineSeconds.push_back(fine.seconds[k]);
          if (l > 0) level.coarse.push_back(coarse.values[k]), coarseSeconds.push_back(coarse.seconds[k]);
          diff.push_back(fine.values[k] - (l > 0 ? coarse.values[k] : 0.0));
        }
        if (diff.size() < 2)
          throw RunError("level " + std::to_string(l) + ": fewer than two of " + std::to_string(counts[l]) +
                         " samples succeeded" + (level.failures.empty() ? "" : " (" + level.failures.front().message + ")"));
        level.difference = sampling::levelStatistics(diff);
        level.quantity = sampling::levelStatistics(level.fine);
        level.fineSeconds = meanOf(fineSeconds), level.coarseSeconds = meanOf(coarseSeconds);
        stats.push_back(level.difference);
        variance.push_back(level.difference.variance);
        cost.push_back(options.costs.empty() ? std::max(level.fineSeconds + level.coarseSeconds, 1e-6) : options.costs[l]);
      }
      r.estimate = sampling::combine(stats);
      r.targetSe = options.absoluteSe > 0 ? options.absoluteSe : options.relativeSe * std::abs(r.estimate.mean);
      if (!(r.targetSe > 0))
        throw RunError("the estimate of " + options.quantity + " is 0: a relative standard error has no scale; give --se-absolute");
      const MultilevelLevel& top = r.levels.back();
      r.plainSamples = std::ceil(top.quantity.variance / (r.targetSe * r.targetSe));
      r.plainSeconds = r.plainSamples * top.fineSeconds;
      const std::vector<std::size_t> want = sampling::optimalCounts(variance, cost, r.targetSe, options.pilot);
      bool more = false;
      next = counts;
      for (std::size_t l = 0; l < L; ++l)
        if (want[l] > counts[l]) next[l] = std::min<std::uint64_t>(want[l], kMaxPlannedSamples), more = true;
      std::cout << "round " << r.rounds << ": " << options.quantity << " = " << formatNumber(r.estimate.mean) << " +- "
                << formatNumber(r.estimate.se) << " (target " << formatNumber(r.targetSe) << "); samples per level";
      for (std::uint64_t c : counts) std::cout << ' ' << c;
      if (more) {
        std::cout << " ->";
        for (std::uint64_t c : next) std::cout << ' ' << c;
      }
      std::cout << std::endl;
      if (!more) next.clear();
    }
    mpi.broadcast(next);
    if (next.empty()) break;
    counts = next;
  }
  return r;
}

void writeMultilevelCsv(const std::filesystem::path& levels, const std::filesystem::path& summary,
                        const MultilevelResult& r) {
  std::ostringstream a;
  a.precision(17);
  a << "level,nx,ny,pairs,failed,mean_Q,var_Q,mean_Y,var_Y,se_Y,fine_s,coarse_s\n";
  std::size_t pairs = 0;
  double seconds = 0;
  for (std::size_t l = 0; l < r.levels.size(); ++l) {
    const MultilevelLevel& v = r.levels[l];
    const auto n = static_cast<double>(v.difference.count);
    pairs += v.difference.count;
    seconds += n * (v.fineSeconds + v.coarseSeconds);
    a << l << ',' << v.nx << ',' << v.ny << ',' << v.difference.count << ',' << v.failures.size() << ','
      << v.quantity.mean << ',' << v.quantity.variance << ',' << v.difference.mean << ',' << v.difference.variance << ','
      << std::sqrt(v.difference.variance / n) << ',' << v.fineSeconds << ',' << v.coarseSeconds << '\n';
  }
  writeFileAtomically(levels, a.str());
  std::ostringstream b;
  b.precision(17);
  b << "quantity,unit,estimate,se,target_se,grids,pairs,rounds,sample_seconds,threads_per_sample,plain_mc_samples,"
       "plain_mc_seconds\n"
    << r.quantity << ',' << r.unit << ',' << r.estimate.mean << ',' << r.estimate.se << ',' << r.targetSe << ','
    << r.levels.size() << ',' << pairs << ',' << r.rounds << ',' << seconds << ',' << threadsPerSample() << ','
    << r.plainSamples << ',' << r.plainSeconds << '\n';
  writeFileAtomically(summary, b.str());
}

void printMultilevel(std::ostream& out, const MultilevelResult& r) {
  std::vector<std::vector<std::string>> rows;
  double seconds = 0;
  for (std::size_t l = 0; l < r.levels.size(); ++l) {
    const MultilevelLevel& v = r.levels[l];
    const auto n = static_cast<double>(v.difference.count);
    seconds += n * (v.fineSeconds + v.coarseSeconds);
    rows.push_back({std::to_string(l), std::to_string(v.nx) + "x" + std::to_string(v.ny), std::to_string(v.difference.count),
                    std::to_string(v.failures.size()), formatNumber(v.quantity.mean), formatNumber(v.difference.mean),
                    formatNumber(v.difference.variance), formatNumber(std::sqrt(v.difference.variance / n)),
                    formatNumber(v.fineSeconds + v.coarseSeconds, 3)});
  }
  printTable(out, {"level", "grid", "pairs", "failed", "mean Q_l", "mean Y_l", "var Y_l", "se Y_l", "s/sample"}, rows);
  for (const MultilevelLevel& v : r.levels)
    for (const SampleFailure& f : v.failures) out << "  left out: " << f.message << '\n';
  out << r.quantity << " = " << formatNumber(r.estimate.mean) << " +- " << formatNumber(r.estimate.se) << ' ' << r.unit
      << " (standard error; target " << formatNumber(r.targetSe) << ", 95% interval +-" << formatNumber(1.96 * r.estimate.se)
      << ") in " << r.rounds << " round(s); " << formatNumber(seconds, 3) << " s of samples on " << threadsPerSample()
      << " thread(s) each, " << r.computed << " computed by this run\n"
      << "plain Monte Carlo on the finest grid to the same standard error: about " << formatNumber(r.plainSamples, 3)
      << " samples, " << formatNumber(r.plainSeconds, 3) << " s\n";
}

}  // namespace peristep::host
