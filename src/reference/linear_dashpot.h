#pragma once

#include "reference/collision_ode.h"

namespace DiskImpact
{
  namespace Reference
  {
    /**
     * The coefficient of restitution of the linear dashpot
     * xi'' + 2 beta xi' + omega0^2 xi = 0 (Schwager & Pöschel 2007), the
     * collision ending when the force m (omega0^2 xi + 2 beta xi') returns to
     * zero (eq. 17): epsilon = exp(-beta t_c) (eq. 20), with omega =
     * sqrt(omega0^2 - beta^2), Omega = sqrt(beta^2 - omega0^2) and omega t_c =
     * pi - arctan(2 beta omega / (omega^2 - beta^2)), beta < omega0 / sqrt(2);
     *   omega t_c = arctan(2 beta omega / (beta^2 - omega^2)),
     *               omega0 / sqrt(2) <= beta < omega0;
     *   Omega t_c = ln((beta + Omega) / (beta - Omega)),  beta > omega0;
     * and beta = omega0 as the limit t_c = 2 / beta. The printed eq. 21 has
     * omega^2 - beta^2 in the middle branch, which gives epsilon > 1
     * (docs/theory/misprints.md).
     */
    double
    dashpot_restitution(double beta, double omega0);

    /// The middle branch of eq. 21 as printed (for the misprint record).
    double
    dashpot_restitution_printed_middle_branch(double beta, double omega0);

    /**
     * The naive criterion, the collision ending when the overlap returns to
     * zero (Schwager & Pöschel 2007, eq. 15): exp(-beta pi / omega) below
     * critical damping; above it the overlap never returns (epsilon = 0,
     * capture).
     */
    double
    dashpot_restitution_overlap_criterion(double beta, double omega0);

    /**
     * The dashpot as the general collision ODE (collide()) with m = 1:
     * F = omega0^2 xi and A F' = 2 beta, from xi' = 1, ended by @p end.
     */
    Collision
    dashpot_collision(double beta, double omega0, EndCriterion end);
  } // namespace Reference
} // namespace DiskImpact
