#pragma once
// The ranges and fixed values of the scene parameters that the FMI layer declares and binds, from the
// layers that define them: grid sizes, horizon and jitter (geometry/point_cloud.hpp), Poisson's ratio
// (models/poisson_ratio.hpp), the jitter of the 002 bar's stochastic grid (geometry/bar_grid.hpp). The FMI
// layer reads numerics only through scenes/.
#include "geometry/bar_grid.hpp"
#include "geometry/point_cloud.hpp"
#include "models/poisson_ratio.hpp"
