#include "restitution/dem_inputs.h"

#include <cmath>
#include <iomanip>
#include <regex>
#include <sstream>

namespace DiskImpact
{
  std::string
  ten_digits(const double value)
  {
    std::ostringstream text;
    text << std::setprecision(10) << value;
    return text.str();
  }

  namespace
  {
    /// What every DEM file's header states, in SI.
    struct LawFacts
    {
      double radius, density, young, poisson, speed, epsilon, contact_time,
        friction;
    };

    /// The facts of a sphere's (DemInputs) or a disk's (DiskDemInputs) law.
    template <typename Inputs>
    LawFacts
    facts_of(const Inputs &d)
    {
      return {d.radius,
              d.density,
              d.young,
              d.poisson,
              d.speed,
              d.epsilon,
              d.contact_time,
              d.friction};
    }

    /// The header: the particle, epsilon and the contact time at the
    /// reference speed, and mu if the contact has friction.
    std::string
    law_header(const std::string &units,
               const std::string &body,
               const std::string &bodies,
               const LawFacts    &f)
    {
      std::ostringstream head;
      head << "# diskimpact restitution law (" << units << "): " << body
           << " of radius " << ten_digits(f.radius) << " m, density "
           << ten_digits(f.density) << " kg/m^3, E = " << ten_digits(f.young)
           << " Pa, nu = " << ten_digits(f.poisson)
           << ".\n# At the reference speed " << ten_digits(f.speed)
           << " m/s on a rigid wall (or two such " << bodies
           << " at relative speed " << ten_digits(2. * f.speed)
           << " m/s): epsilon = " << ten_digits(f.epsilon) << ", contact time "
           << ten_digits(f.contact_time) << " s.\n";
      if (f.friction > 0.)
        head << "# Coulomb friction coefficient mu = " << ten_digits(f.friction)
             << " (diskimpact's 'Friction coefficient').\n";
      return head.str();
    }

    /// LIGGGHTS' elastic-plastic contact of a plastic sphere (DemInputs).
    std::string
    liggghts_thornton_file(const DemInputs &d, const std::string &header)
    {
      return header +
             "# LIGGGHTS, model thornton_ning without adhesion (surfaceEnergy "
             "0): Hertz up to the\n# contact radius a_y = "
             "coefficientYieldRatio x R, then Thornton's plastic loading "
             "at the\n# limiting pressure p_y = " +
             ten_digits(d.limiting_pressure) +
             " Pa fitted to diskimpact's epsilon(v) (the model's v_y = " +
             ten_digits(d.yield_speed) +
             " m/s);\n# epsilon falls with the speed "
             "(restitution_law.csv, epsilon_thornton_fit). "
             "coefficientRestitution\n# only damps the tangential spring.\n"
             "hard_particles yes\n"
             "fix m1 all property/global youngsModulus peratomtype " +
             ten_digits(d.young) +
             "\nfix m2 all property/global poissonsRatio peratomtype " +
             ten_digits(d.poisson) +
             "\nfix m3 all property/global coefficientRestitution "
             "peratomtypepair 1 " +
             ten_digits(d.liggghts_restitution) +
             "\nfix m4 all property/global coefficientFriction peratomtypepair "
             "1 " +
             ten_digits(d.friction) +
             "\nfix m5 all property/global surfaceEnergy peratomtypepair 1 0"
             "\nfix m6 all property/global coefficientYieldRatio peratomtype " +
             ten_digits(liggghts_yield_ratio(d)) +
             "\npair_style gran model thornton_ning tangential history\n"
             "pair_coeff * *\n";
    }

    /// Yade's elastic-plastic contact of a plastic sphere (DemInputs).
    std::string
    yade_luding_file(const DemInputs &d, const std::string &header)
    {
      const double a = d.luding_kp / d.luding_k1 - 1.;
      return "# Yade, LudingMat (Luding's linear elastic-plastic contact) "
             "without adhesion and viscosity\n" +
             header +
             "# Loading stiffness k1, unloading stiffness growing with the "
             "largest overlap up to kp at\n# the plasticity depth (PhiF): "
             "kp / k1 = " +
             ten_digits(d.luding_kp / d.luding_k1) +
             " and v_p = " + ten_digits(d.luding_plastic_speed) +
             " m/s fitted to diskimpact's epsilon(v)\n# "
             "(restitution_law.csv, epsilon_luding_fit): epsilon = (1 + " +
             ten_digits(a) + " v / v_p)^(-1/2) up to v_p, then\n# (1 - " +
             ten_digits(a / (1. + a)) +
             " (v_p / v)^2)^(1/2). For two such spheres: Yade gives a "
             "sphere's contact with\n# a wall no plasticity depth. tc: the "
             "model's contact time at the reference speed.\ntc = " +
             ten_digits(d.contact_time) +
             "\nmat = O.materials.append(LudingMat(k1=" +
             ten_digits(d.luding_k1) + ", kp=" + ten_digits(d.luding_kp) +
             ", kc=0., PhiF=" + ten_digits(d.luding_phi_f) +
             ", G0=0., ks=0., frictionAngle=0., density=" +
             ten_digits(d.density) + "))\n";
    }
  } // namespace

  void
  set_luding_inputs(DemInputs   &d,
                    const double stiffness_ratio,
                    const double plastic_speed)
  {
    const double a = stiffness_ratio - 1.;
    const double tau =
      Reference::luding_contact_time(d.speed / plastic_speed, a);
    d.luding_k1 = d.mass * tau * tau / (2. * d.contact_time * d.contact_time);
    d.luding_kp = stiffness_ratio * d.luding_k1;
    const double depth = plastic_speed * std::sqrt(2. * d.mass / d.luding_k1);
    d.luding_phi_f     = depth * a / (stiffness_ratio * d.radius);
    d.luding_plastic_speed = plastic_speed;
  }

  double
  liggghts_yield_ratio(const DemInputs &d)
  {
    const double e_star = d.young / (1. - d.poisson * d.poisson);
    return M_PI * d.limiting_pressure / (2. * e_star);
  }

  std::map<std::string, std::string>
  dem_files(const DemInputs &d)
  {
    std::ostringstream head;
    head << law_header("SI units", "a sphere", "spheres", facts_of(d));
    const std::string                  mu      = ten_digits(d.friction);
    const bool                         sliding = d.friction > 0.;
    std::map<std::string, std::string> files;
    files["liggghts.txt"] =
      head.str() +
      "# LIGGGHTS, model hertz: its damping keeps epsilon constant in v; "
      "coefficientRestitution\n# is the input for which LIGGGHTS' model "
      "gives epsilon = " +
      ten_digits(d.liggghts_epsilon) +
      ".\n# A wall must have a much larger youngsModulus to act as the "
      "rigid wall; 'hard_particles yes' allows E > 1e9 Pa.\n"
      "hard_particles yes\n"
      "fix m1 all property/global youngsModulus peratomtype " +
      ten_digits(d.young) +
      "\nfix m2 all property/global poissonsRatio peratomtype " +
      ten_digits(d.poisson) +
      "\nfix m3 all property/global coefficientRestitution peratomtypepair "
      "1 " +
      ten_digits(d.liggghts_restitution) +
      "\nfix m4 all property/global coefficientFriction peratomtypepair 1 " +
      mu + "\n" +
      (sliding ? "# tangential history: Mindlin's no-slip stiffness 8 G* a, "
                 "damped as the normal spring.\n" :
                 "") +
      "pair_style gran model hertz tangential history\npair_coeff * *\n";
    files["lammps.txt"] =
      head.str() +
      "# LAMMPS pair granular, Hertz with viscoelastic damping: Ramírez et "
      "al.'s "
      "law with the fitted A = " +
      ten_digits(d.A) +
      " s,\n# eta_n0 = 2 A E_eff / m_eff, the velocity dependence "
      "included.\n" +
      (sliding ? "# tangential mindlin: k_t = 8 G_eff a from E and nu "
                 "(NULL), damping x_gamma_t = 1 times the normal one, mu.\n" :
                 "") +
      "pair_style granular\npair_coeff * * hertz/material " +
      ten_digits(d.young) + " " + ten_digits(d.lammps_damping) + " " +
      ten_digits(d.poisson) +
      (sliding ? " tangential mindlin NULL 1.0 " + mu :
                 std::string(" tangential linear_nohistory 0.0 0.0")) +
      " damping viscoelastic\n";
    files["yade.py"] =
      "# Yade, ViscElMat (linear spring-dashpot from contact time and "
      "restitution)\n" +
      head.str() +
      "# ViscElMat's force is never attractive: its epsilon exceeds en "
      "and its contact time differs\n# from tc. These en, tc give the "
      "epsilon and contact time above, at every speed.\n" +
      std::string(sliding ?
                    "# With friction: et = 1, an undamped tangential spring "
                    "2/7 of the normal one (the same period).\n" :
                    "") +
      "mat = O.materials.append(ViscElMat(en=" + ten_digits(d.yade.epsilon) +
      ", et=" + (sliding ? "1." : "0.") +
      ", tc=" + ten_digits(d.yade.contact_time) +
      ", density=" + ten_digits(d.density) +
      ", frictionAngle=" + (sliding ? "atan(" + mu + ")" : std::string("0.")) +
      "))\n";
    files["mercurydpm.txt"] =
      "// MercuryDPM, LinearViscoelasticSpecies (particle-wall; for two "
      "such particles use mass / 2)\n" +
      std::regex_replace(head.str(), std::regex("(^|\n)# "), "$1// ") +
      (sliding ? "// LinearViscoelasticSlidingFrictionSpecies: the sliding "
                 "spring and dashpot 2/7 of the normal ones (the same "
                 "period).\n" :
                 "") +
      "species.setDensity(" + ten_digits(d.density) +
      ");\nspecies.setCollisionTimeAndRestitutionCoefficient(" +
      ten_digits(d.contact_time) + ", " + ten_digits(d.epsilon) + ", " +
      ten_digits(d.mass) + ");\n" +
      (sliding ? "species.setSlidingFrictionCoefficient(" + mu +
                   ");\nspecies.setSlidingStiffness(2. / 7. * "
                   "species.getStiffness());\nspecies.setSlidingDissipation("
                   "2. / 7. * species.getDissipation());\n" :
                 "");
    files["lethe.prm"] =
      head.str() +
      "# Lethe (lethe-particles), subsection lagrangian physical "
      "properties, particle type 0:\n"
      "set diameter                          = " +
      ten_digits(2. * d.radius) +
      "\nset density particles                 = " + ten_digits(d.density) +
      "\nset young modulus particles           = " + ten_digits(d.young) +
      "\nset poisson ratio particles           = " + ten_digits(d.poisson) +
      "\nset restitution coefficient particles = " + ten_digits(d.epsilon) +
      "\nset friction coefficient particles    = " + mu + "\n";
    if (d.limiting_pressure > 0.)
      files["liggghts_thornton.txt"] = liggghts_thornton_file(d, head.str());
    if (d.luding_k1 > 0.)
      files["yade_luding.py"] = yade_luding_file(d, head.str());
    return files;
  }

  std::map<std::string, std::string>
  dem_disk_files(const DiskDemInputs &d)
  {
    const bool         sliding = d.friction > 0.;
    std::ostringstream text;
    text << law_header("SI units, per unit thickness",
                       "a disk in " + d.plane,
                       "disks",
                       facts_of(d));
    text << "# LAMMPS in 2D: 'dimension 2', 'atom_style sphere', the disks' "
            "mass rho pi R^2 per unit\n# thickness with 'set ... density/disc "
         << ten_digits(d.density)
         << "', their moment of inertia m R^2/2 with\n# 'fix ... nve/sphere "
            "disc'. A linear spring-dashpot (hooke k_n eta_n, damping "
            "velocity)\n# between two such disks: constant epsilon and "
            "contact time, diskimpact's at the\n# reference speed (the "
            "elastic disk's law is logarithmic; the linear spring is its "
            "secant).\n# A rigid wall ('fix wall/gran') takes 2 k_n and 2 "
            "eta_n.\n";
    if (sliding)
      text << "# tangential linear_history: the disk's initial tangential "
              "stiffness over its normal one,\n# "
           << ten_digits(d.tangential_ratio)
           << " at the largest contact half-width of the reference speed, a "
              "= "
           << ten_digits(d.half_width)
           << " R (Cattaneo's disk\n# against the disk's contact law), "
              "damped as the normal spring (x_gamma_t = 1).\n";
    text << "pair_style granular\npair_coeff * * hooke "
         << ten_digits(d.pair.stiffness) << " " << ten_digits(d.pair.damping)
         << " tangential "
         << (sliding ? "linear_history " +
                         ten_digits(d.tangential_ratio * d.pair.stiffness) +
                         " 1.0 " + ten_digits(d.friction) :
                       std::string("linear_nohistory 0.0 0.0"))
         << " damping velocity\n";
    return {{"lammps_2d.txt", text.str()}};
  }
} // namespace DiskImpact
