#include <vulkan/vulkan.h>

#include "antumbra/fg/plan.hpp"
