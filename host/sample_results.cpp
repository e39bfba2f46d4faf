#include "sample_results.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "atomic_file.hpp"
#include "hdf5_support.hpp"
#include "host_errors.hpp"
#include "result_files.hpp"
#include "xdmf_writer.hpp"

namespace peristep::host {

namespace {

std::string momentsNote(const LevelResult& r) {
  const std::size_t ok = r.records.size() - r.failures.size();
  if (!r.momentsComputed)
    return r.failures.size() == r.records.size()
               ? "not computed: every sample failed"
               : "not computed: " + std::to_string(r.failures.size()) +
                     " sample(s) failed and the rule's weights do not allow dropping a node";
  if (!r.failures.empty()) return "over the " + std::to_string(ok) + " successful samples, equal weights";
  return "over all samples with the rule's weights";
}

void writeLevel(hid_t file, const LevelResult& r, const std::string& rule, const ResultLayout& layout) {
  const std::string name = "level_" + std::to_string(r.level);
  const hdf5::Handle group = hdf5::createGroup(file, name);
  const std::uint64_t Q = r.records.size();
  writeAttribute(group, {"rule", rule});
  writeAttribute(group, {"level", std::vector<std::uint64_t>{r.level}});
  writeAttribute(group, {"samples", std::vector<std::uint64_t>{Q}});
  writeAttribute(group, {"computed", std::vector<std::uint64_t>{r.computed}});
  writeAttribute(group, {"reused", std::vector<std::uint64_t>{r.reused}});
  writeAttribute(group, {"seconds", std::vector<double>{r.seconds}});
  if (r.errorMean) writeAttribute(group, {"errorMean", std::vector<double>{*r.errorMean}});
  if (r.errorStd) writeAttribute(group, {"errorStd", std::vector<double>{*r.errorStd}});
  if (r.diffMean) writeAttribute(group, {"diffMeanToLastLevel", std::vector<double>{*r.diffMean}});
  if (r.diffStd) writeAttribute(group, {"diffStdToLastLevel", std::vector<double>{*r.diffStd}});

  if (r.plan.set.dims > 0) hdf5::writeDataset(group, "nodes", {Q, r.plan.set.dims}, r.plan.set.points.data());
  hdf5::writeDataset(group, "weights", {Q}, r.plan.set.weights.data());
  if (!r.plan.jobs.empty() && r.plan.jobs.front().seed) {
    std::vector<double> seeds;
    for (const SampleJob& j : r.plan.jobs) seeds.push_back(static_cast<double>(*j.seed));
    hdf5::writeDataset(group, "seeds", {Q}, seeds.data());
  }

  if (!r.failures.empty()) {
    std::vector<std::uint64_t> failed;
    std::string messages;
    for (const SampleFailure& f : r.failures) failed.push_back(f.index + 1), messages += f.message + '\n';
    writeAttribute(group, {"failedSamples", failed});  // 1-based job numbers; their rows are NaN
    writeAttribute(group, {"failureMessages", messages});
  }
  writeAttribute(group, {"failed", std::vector<std::uint64_t>{r.failures.size()}});
  writeAttribute(group, {"moments", momentsNote(r)});

  // Every statistic in its own group, named for what it is; the group's "estimate" attribute says how.
  const auto statistic = [&](const std::string& name, const std::string& estimate,
                             std::vector<double> Moments::*member) {
    if ((r.scalarMoments.*member).empty() && (r.fieldMoments.empty() || (r.fieldMoments.front().*member).empty()))
      return;
    const hdf5::Handle g = hdf5::createGroup(group, name);
    writeAttribute(g, {"estimate", estimate});
    for (std::size_t i = 0; i < layout.scalars.size(); ++i)
      hdf5::writeDataset(g, layout.scalars[i].name, {}, &(r.scalarMoments.*member)[i]);
    for (std::size_t f = 0; f < layout.fields.size(); ++f)
      hdf5::writeDataset(g, layout.fields[f].name, layout.fields[f].shape, (r.fieldMoments[f].*member).data());
  };
  statistic("mean", "sum_k w_k q_k, 000:(3.10)", &Moments::mean);
  statistic("std", "direct estimate with the rule's weights (Monte Carlo: 1/Q): sqrt(sum_k w_k (q_k - mean)^2), "
            "000:(3.11), 0 where the sum is negative", &Moments::std);
  statistic("pce_std", "sparse pseudo-spectral surrogate (Constantine-Eldred-Phipps 2012): sqrt of the sum of the "
            "squared non-constant coefficients", &Moments::pceStd);
  statistic("se_mean", "Monte Carlo standard error of the mean: s/sqrt(Q), s^2 = sum (q_k - mean)^2/(Q-1); 95% "
            "interval of the mean: mean -+ 1.96 se_mean", &Moments::seMean);
  statistic("se_variance", "Monte Carlo standard error of std^2: sqrt((m4 - m2^2)/Q), m_j = sum (q_k - mean)^j/Q",
            &Moments::seVar);
  statistic("se_std", "Monte Carlo standard error of std: se_variance/(2 std) (delta method)", &Moments::seStd);

  const hdf5::Handle samples = hdf5::createGroup(group, "samples");
  for (std::size_t i = 0; i < layout.scalars.size(); ++i) {
    std::vector<double> v;
    for (const SampleRecord& s : r.records) v.push_back(s.scalars[i]);
    hdf5::writeDataset(samples, layout.scalars[i].name, {Q}, v.data());
  }
  for (std::size_t f = 0; f < layout.fields.size(); ++f) {
    const ArrayInfo& info = layout.fields[f];
    std::vector<std::uint64_t> shape{Q};
    shape.insert(shape.end(), info.shape.begin(), info.shape.end());
    std::vector<double> all;
    for (const SampleRecord& s : r.records) all.insert(all.end(), s.fields[f].begin(), s.fields[f].end());
    hdf5::writeDataset(samples, info.name, shape, all.data());
  }
}

// The points as the study's XDMF file reads them: x and y interleaved, [ny][nx][2] (ParaView's XDMF 3
// reader takes no separate X_Y geometry).
void writeXdmfGeometry(hid_t file, const ResultLayout& layout) {
  const std::vector<double>* x = nullptr;
  const std::vector<double>* y = nullptr;
  for (std::size_t i = 0; i < layout.constantArrays.size(); ++i)
    if (layout.onGrid(layout.constantArrays[i])) {
      if (layout.constantArrays[i].name == "x") x = &layout.constantValues[i];
      if (layout.constantArrays[i].name == "y") y = &layout.constantValues[i];
    }
  if (!x || !y) return;
  std::vector<double> xy(2 * x->size());
  for (std::size_t k = 0; k < x->size(); ++k) xy[2 * k] = (*x)[k], xy[2 * k + 1] = (*y)[k];
  const hdf5::Handle group = hdf5::createGroup(file, "xdmf");
  hdf5::writeDataset(group, "xy", {layout.ny, layout.nx, 2}, xy.data());
}

}  // namespace

void writeStudyHdf5(const std::filesystem::path& file, const StudyDescription& study, const ResultLayout& layout,
                    const std::vector<LevelResult>& levels) {
  const std::filesystem::path partial = partialName(file);
  asRunError([&] {
    hdf5::Handle f = hdf5::createFile(partial.string());
    writeAttribute(f, {"scene", study.scene});
    writeAttribute(f, {"rule", study.rule});
    for (const Attribute& a : study.attributes) writeAttribute(f, a);
    const hdf5::Handle grid = hdf5::createGroup(f, "grid");
    for (std::size_t i = 0; i < layout.constantArrays.size(); ++i)
      hdf5::writeDataset(grid, layout.constantArrays[i].name, layout.constantArrays[i].shape, layout.constantValues[i].data());
    writeXdmfGeometry(f, layout);
    for (const LevelResult& r : levels) writeLevel(f, r, study.rule, layout);
    f.close("close " + partial.string());
  });
  std::error_code ec;
  std::filesystem::rename(partial, file, ec);
  if (ec) throw RunError("cannot rename " + partial.string() + " to " + file.string() + ": " + ec.message());
}

void writeStudyCsv(const std::filesystem::path& file, const ResultLayout& layout, const std::vector<LevelResult>& levels) {
  const SampleRule rule = levels.empty() ? SampleRule::Tensor : levels.front().rule;
  std::ostringstream out;
  out << "level,samples,computed,errorMean,errorStd,diffMean,diffStd,seconds,failed";
  for (const ArrayInfo& s : layout.scalars) {
    out << ",mean_" << s.name << ",std_" << s.name;
    if (rule == SampleRule::Smolyak) out << ",pceStd_" << s.name;
    if (rule == SampleRule::MonteCarlo) out << ",seMean_" << s.name << ",seStd_" << s.name << ",seVariance_" << s.name;
  }
  out << '\n';
  char buf[64];
  const auto num = [&](double v) {  // empty for NaN: no value (moments not computed, Q = 1)
    if (std::isnan(v)) return std::string();
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return std::string(buf);
  };
  for (const LevelResult& r : levels) {
    const auto opt = [&](const std::optional<double>& v) { return v ? num(*v) : std::string(); };
    out << r.level << ',' << r.records.size() << ',' << r.computed << ',' << opt(r.errorMean) << ','
        << opt(r.errorStd) << ',' << opt(r.diffMean) << ',' << opt(r.diffStd) << ',' << num(r.seconds) << ','
        << r.failures.size();
    const Moments& m = r.scalarMoments;
    for (std::size_t i = 0; i < layout.scalars.size(); ++i) {
      out << ',' << num(m.mean[i]) << ',' << num(m.std[i]);
      if (rule == SampleRule::Smolyak) out << ',' << num(m.pceStd[i]);
      if (rule == SampleRule::MonteCarlo) out << ',' << num(m.seMean[i]) << ',' << num(m.seStd[i]) << ',' << num(m.seVar[i]);
    }
    out << '\n';
  }
  writeFileAtomically(file, out.str());
}

void writeStudyXdmfFile(const std::filesystem::path& xmf, const std::filesystem::path& hdf5File,
                        const ResultLayout& layout, const std::vector<LevelResult>& levels) {
  std::vector<StudyXdmfLevel> described;
  for (const LevelResult& r : levels) {
    StudyXdmfLevel level{r.level, r.records.size(), {}, {}};
    const std::pair<const char*, std::vector<double> Moments::*> statistics[] = {
        {"mean", &Moments::mean}, {"std", &Moments::std}, {"pce_std", &Moments::pceStd}, {"se_mean", &Moments::seMean}};
    for (const auto& [name, member] : statistics) {
      if (!r.fieldMoments.empty() && !(r.fieldMoments.front().*member).empty()) level.statistics.push_back(name);
      if ((r.scalarMoments.*member).size() != layout.scalars.size()) continue;
      for (std::size_t i = 0; i < layout.scalars.size(); ++i)
        if (const double v = (r.scalarMoments.*member)[i]; std::isfinite(v))
          level.scalars.emplace_back(std::string(name) + "_" + layout.scalars[i].name, v);
    }
    described.push_back(std::move(level));
  }
  writeStudyXdmf(xmf, layout, hdf5File.filename().string(), described);
}

}  // namespace peristep::host
