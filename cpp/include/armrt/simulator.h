// Deprecated name of armrt::Arm (arm.h), kept while the runner and tests move over.
#pragma once

#include "armrt/arm.h"

namespace armrt {
using Simulator = Arm;
}  // namespace armrt
