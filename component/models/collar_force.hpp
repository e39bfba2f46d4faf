#pragma once
// The force a Dirichlet collar exerts on the domain: the grip's reaction, shared by the quasi-static
// solvers with and without fracture.
#include <array>
#include <cstdint>
#include <vector>

#include "models/lps_discretization.hpp"

namespace peristep {

// Net force per unit thickness [N/m] of the points marked in `collar` on the domain points, through the
// intact bonds between them (the negated summands of 000:(3.19)). lambda, mu: per point; u: (u_x, u_y)
// of every point; x: the solution vector (theta read from it); intact: per CSR entry, null when every bond
// is intact.
std::array<double, 2> collarForce(const LpsDiscretization& d, const std::vector<double>& lambda,
                                  const std::vector<double>& mu, const std::vector<double>& u,
                                  const std::vector<double>& x, const std::vector<std::uint8_t>& collar,
                                  const std::vector<std::uint8_t>* intact = nullptr);

}  // namespace peristep
