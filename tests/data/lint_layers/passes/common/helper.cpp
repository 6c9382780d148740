#include "alpha/alpha_pass.hpp"
