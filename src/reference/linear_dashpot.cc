#include "reference/linear_dashpot.h"

#include <cmath>

namespace DiskImpact
{
  namespace Reference
  {
    double
    dashpot_restitution(const double beta, const double omega0)
    {
      double contact_time;
      if (beta < omega0)
        {
          const double omega = std::sqrt(omega0 * omega0 - beta * beta);
          const double ratio = 2. * beta * omega;
          const double gap   = omega * omega - beta * beta;
          contact_time =
            gap > 0. ?
              (M_PI - std::atan(ratio / gap)) / omega :
              (gap < 0. ? std::atan(ratio / -gap) : 0.5 * M_PI) / omega;
        }
      else if (beta > omega0)
        {
          const double big_omega = std::sqrt(beta * beta - omega0 * omega0);
          contact_time =
            std::log((beta + big_omega) / (beta - big_omega)) / big_omega;
        }
      else
        contact_time = 2. / beta;
      return std::exp(-beta * contact_time);
    }

    double
    dashpot_restitution_printed_middle_branch(const double beta,
                                              const double omega0)
    {
      const double omega = std::sqrt(omega0 * omega0 - beta * beta);
      return std::exp(
        -beta / omega *
        std::atan(2. * beta * omega / (omega * omega - beta * beta)));
    }

    double
    dashpot_restitution_overlap_criterion(const double beta,
                                          const double omega0)
    {
      if (beta >= omega0)
        return 0.;
      const double omega = std::sqrt(omega0 * omega0 - beta * beta);
      return std::exp(-beta * M_PI / omega);
    }

    Collision
    dashpot_collision(const double       beta,
                      const double       omega0,
                      const EndCriterion end)
    {
      const double   k = omega0 * omega0;
      const ForceLaw law{[k](const double xi) { return k * xi; },
                         [k](double) { return k; }};
      return collide(1., 1., law, 2. * beta / k, end);
    }
  } // namespace Reference
} // namespace DiskImpact
