#include "dynamics/anderson_acceleration.h"

#include <catch2/catch.hpp>

using namespace DiskImpact;
using namespace dealii;

TEST_CASE("Anderson acceleration: a slowly contracting linear map",
          "[anderson]")
{
  // x = G x + c with G = diag(0.99, 0.5, -0.9, 0.95): plain iteration
  // needs thousands of steps for 1e-12; with depth 5 the residuals of a
  // linear map of dimension 4 are cancelled within a few more steps.
  const std::vector<double> g{0.99, 0.5, -0.9, 0.95}, c{1., -2., 0.5, 3.};
  Vector<double>            x(4), fixed(4);
  for (unsigned int i = 0; i < 4; ++i)
    fixed[i] = c[i] / (1. - g[i]);
  AndersonAcceleration<> acceleration(5);
  unsigned int         steps = 0;
  for (; steps < 50; ++steps)
    {
      Vector<double> f(4);
      for (unsigned int i = 0; i < 4; ++i)
        f[i] = g[i] * x[i] + c[i] - x[i];
      if (f.linfty_norm() < 1e-12)
        break;
      x = acceleration.next(x, f);
    }
  CHECK(steps <= 10);
  for (unsigned int i = 0; i < 4; ++i)
    CHECK(x[i] == Approx(fixed[i]).epsilon(1e-10));
}
