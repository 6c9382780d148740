#include "alpha_pass.hpp"
#include "beta/beta_pass.hpp"

bool compute(const Json& params) {
  return params.find("rasterizer") != params.end();
}
