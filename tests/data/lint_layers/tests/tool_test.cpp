#include "alpha/alpha_pass.hpp"
#include "antumbra/fg/plan.hpp"
#include "commands.hpp"
