#pragma once
// A geometry header that reaches up into scenes/: the layering check must refuse it.
#include "scenes/spec.hpp"
