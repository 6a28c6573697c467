#pragma once

namespace DiskImpact
{
  /// How the contact force of a time step is formed from the gaps at its
  /// start (g0) and end (g1): a choice of the time integrator, which the
  /// contact zone carries out.
  enum class ContactAverage
  {
    trapezoidal,      ///< (1 - w) p(g0) + w p(g1): Newmark, generalized-alpha
    discrete_gradient ///< -(E(g1) - E(g0)) / (g1 - g0): conserves energy
  };
} // namespace DiskImpact
