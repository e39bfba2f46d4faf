#include "name_suggestion.hpp"

#include <algorithm>
#include <vector>

namespace peristep::host {

namespace {

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string didYouMean(std::string_view name, const ModelDescription& md) {
  const Variable* best = nullptr;
  std::size_t bestDistance = 3;  // farther than two edits is not a typo
  for (const Variable& v : md.variables)
    if (const std::size_t d = editDistance(name, v.name); d < bestDistance) best = &v, bestDistance = d;
  return best ? " (did you mean " + best->name + "?)" : "";
}

}  // namespace peristep::host
