// A core header that includes a higher module: the layer check must refuse it.
#pragma once
#include "integrator/velocity_verlet.hpp"
