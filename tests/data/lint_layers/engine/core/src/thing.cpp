#include "antumbra/fg/plan.hpp"
