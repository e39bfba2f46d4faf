#pragma once
// Results of a sample study:
//   HDF5  /grid/<x, y>                        point coordinates [ny][nx]
//         /level_<L>/nodes [Q][N], weights [Q], seeds [Q] (Monte Carlo over microstructures)
//         /level_<L>/samples/<output>         every Float64 output per sample, [Q] or [Q][ny][nx]
//         /level_<L>/mean/<output>, std/<output>   000:(3.10)-(3.11), std the direct quadrature estimate
//         /level_<L>/pce_std/<output>         Smolyak: standard deviation of the sparse PCE surrogate
//         /level_<L>/se_mean, se_std, se_variance/<output>   Monte Carlo standard errors
//         (each statistic group has an "estimate" attribute that says how it is computed)
//         attributes: rule, level, samples, computed, reused, failed, failedSamples, failureMessages,
//                     moments (over which samples), seconds, errorMean/errorStd (if known)
//   CSV   one row per level: samples, computed, errors, wall time, failed, then per scalar output
//         mean_<o>, std_<o> (direct estimate with the rule's weights) and pceStd_<o> (Smolyak) or
//         seMean_<o>, seStd_<o>, seVariance_<o> (Monte Carlo); empty cells where there is no value.
//   XDMF  <stem>.xmf beside the HDF5 file: each level's field statistics on the grid, for ParaView
// The HDF5 file is rewritten after every level under a temporary name and renamed, so it always holds
// the finished levels.
#include <filesystem>
#include <string>
#include <vector>

#include "sample_study.hpp"

namespace peristep::host {

struct StudyDescription {
  std::string scene, rule;
  std::vector<Attribute> attributes;  // provenance written on "/"
};

void writeStudyHdf5(const std::filesystem::path& file, const StudyDescription& study, const ResultLayout& layout,
                    const std::vector<LevelResult>& levels);
void writeStudyCsv(const std::filesystem::path& file, const ResultLayout& layout, const std::vector<LevelResult>& levels);
// The XDMF file beside the HDF5 file (xdmf_writer.hpp): per level the mean, std (and pce_std or
// se_mean) of every field on the grid, for ParaView.
void writeStudyXdmfFile(const std::filesystem::path& xmf, const std::filesystem::path& hdf5File,
                        const ResultLayout& layout, const std::vector<LevelResult>& levels);

}  // namespace peristep::host
