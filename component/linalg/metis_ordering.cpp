#include "linalg/metis_ordering.hpp"

#include <metis.h>

#include <string>

#include "core/errors.hpp"

namespace peristep {

std::mutex& metisMutex() {
  static std::mutex m;
  return m;
}

std::vector<std::int32_t> nestedDissection(std::vector<std::int32_t> xadj, std::vector<std::int32_t> adjacency) {
  static_assert(sizeof(idx_t) == sizeof(std::int32_t), "Debian's METIS has 32-bit indices");
  idx_t vertices = static_cast<idx_t>(xadj.size()) - 1;
  std::vector<idx_t> perm(static_cast<std::size_t>(vertices)), position(perm.size());
  if (vertices == 0) return {};
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;
  const std::lock_guard lock(metisMutex());
  const int status = METIS_NodeND(&vertices, xadj.data(), adjacency.data(), nullptr, options, perm.data(),
                                  position.data());
  if (status != METIS_OK) throw SolverFailure("metis: nested dissection failed with status " + std::to_string(status));
  return {position.begin(), position.end()};
}

}  // namespace peristep
