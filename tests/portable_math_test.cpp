// util/trig.h's sin/cos, log, exp and pow (the path tracer's sampling draws through them so
// that both devices agree to the bit) against double-precision references.
#include <gtest/gtest.h>

#include <cmath>

#include "cl/util/trig.h"

namespace {

TEST(PortableMath, SinCos2PiWithinAFewUlps) {
  double worst = 0;
  for (int i = 0; i < 100000; ++i) {
    float u = static_cast<float>(i) / 100000.0f;
    float s, c;
    SinCos2Pi(u, &s, &c);
    double a = 2 * M_PI * static_cast<double>(u);
    worst = std::max({worst, std::fabs(s - std::sin(a)), std::fabs(c - std::cos(a))});
    ASSERT_LE(s * s + c * c, 1.0f + 4e-7f) << u;
  }
  EXPECT_LE(worst, 3e-7);  // About 2.5 ulps of 1.
  float s, c;
  SinCos2Pi(0.0f, &s, &c);
  EXPECT_EQ(s, 0.0f);
  EXPECT_EQ(c, 1.0f);
  SinCos2Pi(0.25f, &s, &c);
  EXPECT_EQ(s, 1.0f);
}

TEST(PortableMath, LogExpPowRelativeErrorBelow1e6) {
  for (int i = 1; i <= 100000; ++i) {
    float x = static_cast<float>(i) / 100000.0f;
    ASSERT_NEAR(LogF(x), std::log(static_cast<double>(x)), 2e-7 + 2e-7 * std::fabs(std::log(x)))
        << x;
    float y = -80.0f + 160.0f * x;
    ASSERT_NEAR(ExpF(y) / std::exp(static_cast<double>(y)), 1.0, 1e-6) << y;
  }
  for (float e : {1.0f, 2.0f, 51.0f, 201.0f})
    for (int i = 1; i <= 1000; ++i) {
      float x = static_cast<float>(i) / 1000.0f;
      double want = std::pow(static_cast<double>(x), 1.0 / e);
      ASSERT_NEAR(PowUnit(x, 1.0f / e) / want, 1.0, 1e-6) << x << " ^ 1/" << e;
    }
  EXPECT_EQ(PowUnit(0.0f, 0.5f), 0.0f);
  EXPECT_EQ(PowUnit(1.0f, 0.5f), 1.0f);
}

}  // namespace
