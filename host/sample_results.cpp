#include "sample_results.hpp"

#include <cstdio>
#include <fstream>

#include "hdf5_support.hpp"
#include "host_errors.hpp"
#include "result_files.hpp"

namespace peristep::host {

namespace {

void writeLevel(hid_t file, const LevelResult& r, const std::string& rule, const ResultLayout& layout) {
  const std::string name = "level_" + std::to_string(r.level);
  Handle group(createGroup(file, name), H5Gclose, "create " + name);
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

  if (r.plan.set.dims > 0) writeDataset(group, "nodes", {Q, r.plan.set.dims}, r.plan.set.points.data());
  writeDataset(group, "weights", {Q}, r.plan.set.weights.data());
  if (!r.plan.jobs.empty() && r.plan.jobs.front().seed) {
    std::vector<double> seeds;
    for (const SampleJob& j : r.plan.jobs) seeds.push_back(static_cast<double>(*j.seed));
    writeDataset(group, "seeds", {Q}, seeds.data());
  }

  Handle samples(createGroup(group, "samples"), H5Gclose, "create samples");
  Handle mean(createGroup(group, "mean"), H5Gclose, "create mean");
  Handle sd(createGroup(group, "std"), H5Gclose, "create std");
  for (std::size_t i = 0; i < layout.scalars.size(); ++i) {
    std::vector<double> v;
    for (const SampleRecord& s : r.records) v.push_back(s.scalars[i]);
    const std::string& n = layout.scalars[i].name;
    writeDataset(samples, n, {Q}, v.data());
    writeDataset(mean, n, {}, &r.scalarMoments.mean[i]);
    writeDataset(sd, n, {}, &r.scalarMoments.std[i]);
  }
  for (std::size_t f = 0; f < layout.fields.size(); ++f) {
    const ArrayInfo& info = layout.fields[f];
    std::vector<std::uint64_t> shape{Q};
    shape.insert(shape.end(), info.shape.begin(), info.shape.end());
    std::vector<double> all;
    for (const SampleRecord& s : r.records) all.insert(all.end(), s.fields[f].begin(), s.fields[f].end());
    writeDataset(samples, info.name, shape, all.data());
    writeDataset(mean, info.name, info.shape, r.fieldMoments[f].mean.data());
    writeDataset(sd, info.name, info.shape, r.fieldMoments[f].std.data());
  }
}

}  // namespace

void writeStudyHdf5(const std::filesystem::path& file, const StudyDescription& study, const ResultLayout& layout,
                    const std::vector<LevelResult>& levels) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const std::filesystem::path partial = partialName(file);
  {
    Handle f(H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
             "create " + partial.string());
    writeAttribute(f, {"scene", study.scene});
    writeAttribute(f, {"rule", study.rule});
    for (const Attribute& a : study.attributes) writeAttribute(f, a);
    Handle grid(createGroup(f, "grid"), H5Gclose, "create grid");
    for (std::size_t i = 0; i < layout.constantArrays.size(); ++i)
      writeDataset(grid, layout.constantArrays[i].name, layout.constantArrays[i].shape, layout.constantValues[i].data());
    for (const LevelResult& r : levels) writeLevel(f, r, study.rule, layout);
  }
  std::error_code ec;
  std::filesystem::rename(partial, file, ec);
  if (ec) throw RunError("cannot rename " + partial.string() + " to " + file.string() + ": " + ec.message());
}

void writeStudyCsv(const std::filesystem::path& file, const ResultLayout& layout, const std::vector<LevelResult>& levels) {
  std::ofstream out(file);
  out << "level,samples,computed,errorMean,errorStd,diffMean,diffStd,seconds";
  for (const ArrayInfo& s : layout.scalars) out << ",mean_" << s.name << ",std_" << s.name;
  out << '\n';
  char buf[64];
  const auto num = [&](double v) {
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return std::string(buf);
  };
  for (const LevelResult& r : levels) {
    const auto opt = [&](const std::optional<double>& v) { return v ? num(*v) : std::string(); };
    out << r.level << ',' << r.records.size() << ',' << r.computed << ',' << opt(r.errorMean) << ','
        << opt(r.errorStd) << ',' << opt(r.diffMean) << ',' << opt(r.diffStd) << ',' << num(r.seconds);
    for (std::size_t i = 0; i < layout.scalars.size(); ++i)
      out << ',' << num(r.scalarMoments.mean[i]) << ',' << num(r.scalarMoments.std[i]);
    out << '\n';
  }
  if (!out) throw RunError("cannot write " + file.string());
}

}  // namespace peristep::host
