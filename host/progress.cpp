#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace peristep::host {

ProgressBar::ProgressBar(std::string label, std::uint64_t total)
    : label_(std::move(label)), total_(std::max<std::uint64_t>(total, 1)), enabled_(isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {
  update(0, "");
}

ProgressBar::~ProgressBar() {
  if (enabled_) std::cerr << "\r\033[K" << std::flush;
}

double ProgressBar::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressBar::update(std::uint64_t done, const std::string& note) {
  if (!enabled_) return;
  constexpr int width = 30;
  const auto filled = static_cast<int>(width * std::min(done, total_) / total_);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(width, '.');
  char elapsed[32];
  std::snprintf(elapsed, sizeof elapsed, "%.1f s", elapsedSeconds());
  std::cerr << "\r\033[K" << label_ << " [" << bar << "] " << done << "/" << total_ << "  " << elapsed
            << (note.empty() ? "" : "  ") << note << std::flush;
}

void printTable(std::ostream& out, const std::vector<std::string>& header,
                const std::vector<std::vector<std::string>>& rows) {
  // Numbers align right (digits under digits), text aligns left.
  const auto isNumber = [](const std::string& cell) {
    char* end = nullptr;
    std::strtod(cell.c_str(), &end);
    return cell == "-" || cell == "..." || (!cell.empty() && *end == '\0');
  };
  std::vector<std::size_t> width(header.size());
  std::vector<bool> right(header.size(), true);
  for (std::size_t c = 0; c < header.size(); ++c) {
    width[c] = header[c].size();
    for (const auto& row : rows)
      if (c < row.size()) {
        width[c] = std::max(width[c], row[c].size());
        right[c] = right[c] && (row[c].empty() || isNumber(row[c]));
      }
  }
  const auto line = [&](const std::vector<std::string>& cells) {
    std::string text;
    for (std::size_t c = 0; c < header.size(); ++c) {
      const std::string& cell = c < cells.size() ? cells[c] : std::string();
      const std::string pad(width[c] - cell.size(), ' ');
      text += (c ? "  " : "") + (right[c] ? pad + cell : cell + pad);
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    out << text << '\n';
  };
  line(header);
  std::vector<std::string> rule;
  for (std::size_t w : width) rule.emplace_back(w, '-');
  line(rule);
  for (const auto& row : rows) line(row);
}

std::string formatNumber(double v, int precision) {
  if (std::isnan(v)) return "-";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*e", precision - 1, v);
  return buffer;
}

}  // namespace peristep::host
