#pragma once
// Nested symmetric rules: each level's nodes contain the previous level's nodes (as the same doubles),
// so a sparse grid built on them reuses samples across levels.
//   Uniform: Gauss-Patterson, 1, 3, 7, 15, 31 nodes, exact for degree 1, 5, 11, 23, 47.
//   Normal:  Genz-Keister,     1, 3, 9, 19, 35 nodes,     exact for degree 1, 5, 15, 29, 51.
// Level 0 is {0}; level 1 is the 3-point Gauss rule; every further level is a Kronrod-Patterson
// extension of the previous one, computed here in long double and checked for exactness.
// The 19-node Genz-Keister rule has one negative weight (at +-2.86); the others are positive.
#include "rule1d.hpp"

namespace peristep::sampling {

// 0 <= level <= nestedMaxLevel(law) (std::invalid_argument otherwise).
Rule1D nestedRule(Law law, int level);

// Highest level available: 4 for both laws (31 and 35 nodes; see nested_rules.cpp for why).
int nestedMaxLevel(Law law);

// Polynomial degree integrated exactly by nestedRule(law, level).
int nestedRuleDegree(Law law, int level);

}  // namespace peristep::sampling
