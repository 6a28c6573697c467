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
    /// A plastic sphere's Thornton fit (0: elastic, no such file): the
    /// limiting pressure p_y [Pa] and the model's v_y [m/s].
    double limiting_pressure = 0., yield_speed = 0.;
  };

  /// LIGGGHTS' 'coefficientYieldRatio' of the Thornton fit in @p d: the
  /// contact radius of yield over R, a_y / R = pi p_y / (2 E*).
  double
  liggghts_yield_ratio(const DemInputs &d);

  /// What a 2D DEM code needs for a disk, per unit thickness, in SI.
  struct DiskDemInputs
  {
    double      radius, density, young, poisson, speed, epsilon, contact_time;
    std::string plane; ///< "plane strain" or "plane stress"
    /// The mass per unit thickness, rho pi R^2.
    double mass;
    /// The linear spring-dashpot between two such disks (effective mass
    /// m/2) with epsilon and the contact time of the wall at the
    /// reference speed; a wall's spring and dashpot are twice these.
    Reference::LinearSpringDashpot pair;
    /// The tangential spring over the normal one
    /// (Reference::disk_tangential_stiffness_ratio() at the largest contact
    /// half-width of the reference speed) and that half-width over R.
    double tangential_ratio, half_width;
    double friction = 0.;
  };

  /**
   * The inputs of the DEM codes for a sphere with the law @p d: file name
   * (liggghts.txt, lammps.txt, yade.py, mercurydpm.txt, lethe.prm) and
   * text, each in the code's own syntax with a header that states the
   * body and epsilon at the reference speed. With friction, the tangential
   * part: mu and each code's no-slip stiffness (Mindlin's 8 G* a where the
   * code has it, else its linear counterpart), with the tangential damping
   * the code ties to the normal one. For a plastic sphere also
   * liggghts_thornton.txt: LIGGGHTS' 'model thornton_ning' without
   * adhesion with the fitted yield ratio, velocity-dependent like the FE's
   * epsilon (Reference::thornton_ning_epsilon()).
   */
  std::map<std::string, std::string>
  dem_files(const DemInputs &d);

  /**
   * The inputs of 2D DEM codes for a disk with the law @p d: lammps_2d.txt,
   * LAMMPS with 'dimension 2', disks of mass rho pi R^2 per unit thickness
   * ('set ... density/disc') and moment of inertia m R^2 / 2 ('fix
   * nve/sphere disc'), a linear spring-dashpot matched to epsilon and the
   * contact time at the reference speed, with friction a linear tangential
   * spring with the disk's stiffness ratio.
   */
  std::map<std::string, std::string>
  dem_disk_files(const DiskDemInputs &d);

  /// @p value with 10 significant digits.
  std::string
  ten_digits(double value);
} // namespace DiskImpact
