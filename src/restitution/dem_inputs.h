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
    /// A plastic sphere's Luding fit (luding_k1 = 0: none): Yade's
    /// LudingMat k1 [N/m], kp [N/m] and PhiF for two identical spheres
    /// (set_luding_inputs()) and the model's v_p [m/s]; its contact time at
    /// the reference speed is contact_time.
    double luding_k1 = 0., luding_kp = 0., luding_phi_f = 0.,
           luding_plastic_speed = 0.;
  };

  /**
   * Yade's LudingMat in @p d from the wall's fitted kp / k1 =
   * @p stiffness_ratio and v_p = @p plastic_speed [m/s], for two identical
   * spheres (effective mass m/2; Yade's Ip2 puts the plasticity depth of a
   * sphere's contact with a non-sphere to zero): k1 = m tau^2 / (2 t_c^2)
   * with tau = Reference::luding_contact_time() at v_ref / v_p, so that
   * the contact time at the reference speed is d.contact_time;
   * d_p = v_p sqrt(2 m / k1); PhiF = d_p (kp - k1) / (kp R), as Yade's
   * d_p = kp / (kp - k1) PhiF R for two spheres of radius R.
   */
  void
  set_luding_inputs(DemInputs &d, double stiffness_ratio, double plastic_speed);

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
   * epsilon (Reference::thornton_ning_epsilon()), and yade_luding.py:
   * Yade's LudingMat without adhesion with the fitted Luding model
   * (Reference::luding_epsilon()).
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
