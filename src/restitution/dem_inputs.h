#pragma once

#include "reference/dem_contact_models.h"

#include <map>
#include <string>

namespace DiskImpact
{
  /// What a DEM code needs, at the reference speed, in SI.
  struct DemInputs
  {
    double radius, density, young, poisson, mass, speed, epsilon, contact_time,
      liggghts_restitution, liggghts_epsilon, A, lammps_damping;
    /// Coulomb's friction coefficient of the contact ('Friction
    /// coefficient'); 0: the codes' frictionless contact.
    double                            friction = 0.;
    Reference::LinearDashpotCollision yade; ///< ViscElMat's (en, tc)
  };

  /**
   * The inputs of the DEM codes for a sphere with the law @p d: file name
   * (liggghts.txt, lammps.txt, yade.py, mercurydpm.txt, lethe.prm) and
   * text, each in the code's own syntax with a header that states the
   * body and epsilon at the reference speed. With friction, the tangential
   * part: mu and each code's no-slip stiffness (Mindlin's 8 G* a where the
   * code has it, else its linear counterpart), with the tangential damping
   * the code ties to the normal one.
   */
  std::map<std::string, std::string>
  dem_files(const DemInputs &d);

  /// @p value with 10 significant digits.
  std::string
  ten_digits(double value);
} // namespace DiskImpact
