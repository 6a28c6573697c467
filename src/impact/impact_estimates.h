#pragma once

#include "reference/collision_estimate.h"
#include "reference/two_body_contact.h"

#include <string>
#include <utility>

namespace DiskImpact
{
  struct Parameters;

  /**
   * What the impact of Parameters is expected to do, from the 1-DOF
   * reference models (reference/): its contact time, force and overlap, the
   * constants of the wall law, the units of its outputs. The impact
   * simulation's time step, graded mesh and comparisons read them.
   */

  /// The constant of the 1-DOF model's wall law ('One-DOF law constant'): a
  /// disk's C, a sphere's D.
  double
  one_dof_law_constant(const Parameters &parameters);

  /// The contact radius of Hertz's largest approach at the impact speed:
  /// the sphere on the wall, or the pair (subsection Partner).
  double
  hertz_contact_radius(const Parameters &parameters);

  /**
   * An upper bound of the largest approach of a plastic sphere (or pair of
   * spheres; 0 if no body yields, and for disks), which grows beyond
   * Hertz's: a yielding contact's mean pressure stays above the smallest
   * yield stress Y and its contact radius^2 above R delta, so the work of
   * the approach, pi R Y delta^2 / 2 at least, is at most the kinetic
   * energy m v^2 / 2 (the pair's reduced mass and equivalent radius). A
   * disk's approach is mostly its bulk's compression, which no such bound
   * ties to the contact's width.
   */
  double
  plastic_approach_bound(const Parameters &parameters);

  /// A sphere's derived finite-size constant D = D0 + D1 ln(a/R) at
  /// contact radius @p contact_radius; @p body gives R and nu.
  double
  finite_size_constant(const Parameters &body, double contact_radius);

  /// The 1-DOF log-law collision at the impact speed (beyond the log law's
  /// range: Gerl & Zippelius' eq. 61 for the contact time and load); with a
  /// partner body (subsection Partner) the pair's.
  CollisionEstimate
  estimate_collision(const Parameters &parameters);

  /**
   * How far the contact moves along the body's edge as the body turns
   * while in contact: R times the largest angle, the contact time times
   * |omega0| plus the spin friction can add, at most
   * min(2 mu v_n / k, 2 |v_t - omega0 R| / (1 + k)) / R (epsilon <= 1; the
   * contact point at most reversed; k = I / (m R^2), 1/2 a disk, 2/5 a
   * sphere). Zero for a head-on impact without friction and spin.
   */
  double
  contact_drift(const Parameters &parameters);

  /// Throws an InputError unless a fixed 'Time step' suits the contact
  /// time estimate_collision() expects (TimeIntegrator::check_time_step()).
  void
  check_impact_time_step(const Parameters &parameters);

  /// The body and its partner (subsection Partner) as the two-body law
  /// sees them: radius, modulus (E2 of a disk, E* of a sphere) and the
  /// constant of each one's wall law (one_dof_law_constant()).
  std::pair<Reference::ContactBody, Reference::ContactBody>
  contact_bodies(const Parameters &parameters);

  /// The modulus of the contact: the body's E2 against the wall; against
  /// a deformable partner the pair's, 1 / (1 / E2 + 1 / E2').
  double
  contact_modulus(const Parameters &parameters);

  /**
   * The body's dimensionless dissipation: for a disk Schwager's
   * alpha = tau sqrt(pi E2 / m) (Schwager 2007), for a sphere Ramírez et
   * al.'s u = (v / g*)^{1/5} (eq. 32), both with A = tau; 0 if elastic.
   */
  double
  dissipation_parameter(const Parameters &parameters);

  /// The unit of the reported forces: E2 R for a disk (per unit
  /// thickness), E2 R^2 = E* R^2 for a sphere.
  double
  force_unit(const Parameters &parameters);

  /// The units of the outputs, in words (HDF5 attribute, messages).
  std::string
  output_units(const Parameters &parameters);
} // namespace DiskImpact
