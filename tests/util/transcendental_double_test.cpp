// cl/util/transcendental.h in double (`--precision double`), where it replaces the
// libraries' exp, pow, sin and cos too. The header compiles inside its own namespace with
// RT_REAL_DOUBLE, as src/device/cpu/cpu_kernel_double.cpp does.
#define RT_REAL_DOUBLE 1

#include <cmath>

#include "cl/compat.h"

namespace rt_double_math {
#include "cl/util/transcendental.h"
}  // namespace rt_double_math
using namespace rt_double_math;

struct TranscendentalBounds {
  double exp, log, pow, sin_cos, sin_cos_2pi, atan2, acos;
};
// Bounds in double ulps, about 1.3 times the worst measured on the grids (exp 4.3, log 1.7,
// pow 4.1 per unit of |e ln x|, sin/cos 3.4, sin/cos of 2 pi u 3.8, atan2 2.8, acos 3.0).
const TranscendentalBounds kBounds = {6, 2.5, 6, 5, 5, 4, 4};

#define RT_SUITE TranscendentalDouble
#include "support/transcendental_cases.h"
