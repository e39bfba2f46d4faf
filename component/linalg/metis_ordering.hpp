#pragma once
// Nested-dissection ordering of a graph with METIS, for the sparse factorizations that take an ordering.
#include <cstdint>
#include <mutex>
#include <vector>

namespace peristep {

// METIS keeps its random-number state per process: orderings computed at the same time race, and then
// two instances of the same problem would not factor alike. Every METIS call in the library holds this.
std::mutex& metisMutex();

// The elimination position of each vertex of the graph (CSR adjacency, symmetric, no self loops).
std::vector<std::int32_t> nestedDissection(std::vector<std::int32_t> xadj, std::vector<std::int32_t> adjacency);

}  // namespace peristep
