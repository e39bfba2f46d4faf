#pragma once
// Terminal feedback: a progress bar on stderr (drawn only when stderr is a terminal, so logs and
// pipes stay clean) and an aligned summary table.
#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace peristep::host {

class ProgressBar {
 public:
  ProgressBar(std::string label, std::uint64_t total);
  ~ProgressBar();  // clears the bar
  void update(std::uint64_t done, const std::string& note);
  double elapsedSeconds() const;

 private:
  std::string label_;
  std::uint64_t total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
};

// Columns right-aligned to their widest cell; header underlined with dashes.
void printTable(std::ostream& out, const std::vector<std::string>& header,
                const std::vector<std::vector<std::string>>& rows);

// Numbers in tables: 4 significant digits in scientific notation, or "-" for NaN (no value yet).
std::string formatNumber(double v, int precision = 4);

}  // namespace peristep::host
