#pragma once
// The plot of a sample study (`peristep sample`), drawn by gnuplot from the study's CSV: the L2 errors
// of the mean and the standard deviation against the number of samples, log-log, against the exact
// moments (errorMean, errorStd) where the component knows them and against the study's last level
// (diffMean, diffStd) otherwise. Columns are found by their header names.
#include <filesystem>
#include <string>

namespace peristep::host {

inline constexpr unsigned kSamplePlotWidth = 900, kSamplePlotHeight = 500;

// Writes <csv without extension>.png; returns the line to print: "wrote <png>" or why there is no plot.
std::string plotSampleStudy(const std::filesystem::path& csv, const std::string& title);

}  // namespace peristep::host
