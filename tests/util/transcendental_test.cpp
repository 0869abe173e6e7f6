// cl/util/transcendental.h in float: the path tracer's sampling draws through these
// functions so that both devices agree to the bit; here, their accuracy.
#include "cl/util/transcendental.h"

struct TranscendentalBounds {
  double exp, log, pow, sin_cos, sin_cos_2pi, atan2, acos;
};
// Bounds in float ulps, about 1.3 times the worst measured on the grids (exp 0.97, log 0.82,
// pow 2.1 per unit of |e ln x|, sin/cos 13.8 near the zeros at multiples of pi, where Cephes'
// three-part pi/2 limits the reduction, sin/cos of 2 pi u 1.9, atan2 3.0, acos 3.6).
const TranscendentalBounds kBounds = {1.5, 1.5, 3, 16, 3, 4, 5};

#define RT_SUITE TranscendentalFloat
#include "support/transcendental_cases.h"
