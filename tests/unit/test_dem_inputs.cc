#include "restitution/dem_inputs.h"

#include <catch2/catch.hpp>

#include <string>

using namespace DiskImpact;

namespace
{
  /// A steel-like sphere's law with the friction coefficient @p mu.
  DemInputs
  law(const double mu)
  {
    DemInputs d{};
    d.radius = 1e-3, d.density = 7850., d.young = 2.1e11, d.poisson = 0.3;
    d.mass = 3.3e-5, d.speed = 30., d.epsilon = 0.998, d.contact_time = 2.5e-6;
    d.liggghts_restitution = 0.998, d.liggghts_epsilon = 0.998;
    d.A = 1e-9, d.lammps_damping = 1.5e7;
    d.yade     = {0.998, 2.5e-6};
    d.friction = mu;
    return d;
  }

  bool
  contains(const std::string &text, const std::string &part)
  {
    return text.find(part) != std::string::npos;
  }
} // namespace

TEST_CASE("The DEM inputs carry the friction coefficient to every code",
          "[dem]")
{
  const auto files = dem_files(law(0.1));
  CHECK(contains(files.at("liggghts.txt"),
                 "coefficientFriction peratomtypepair 1 0.1\n"));
  CHECK(contains(files.at("liggghts.txt"),
                 "pair_style gran model hertz tangential history\n"));
  CHECK(contains(files.at("lammps.txt"),
                 " tangential mindlin NULL 1.0 0.1 damping viscoelastic\n"));
  CHECK(contains(files.at("yade.py"), "et=1., "));
  CHECK(contains(files.at("yade.py"), "frictionAngle=atan(0.1)"));
  CHECK(contains(files.at("mercurydpm.txt"),
                 "species.setSlidingFrictionCoefficient(0.1);"));
  CHECK(contains(files.at("lethe.prm"),
                 "set friction coefficient particles    = 0.1\n"));
}

TEST_CASE("Without friction the DEM inputs are frictionless", "[dem]")
{
  const auto files = dem_files(law(0.));
  CHECK(contains(files.at("liggghts.txt"),
                 "coefficientFriction peratomtypepair 1 0\n"));
  CHECK(
    contains(files.at("lammps.txt"),
             " tangential linear_nohistory 0.0 0.0 damping viscoelastic\n"));
  CHECK(contains(files.at("yade.py"), "et=0., "));
  CHECK(contains(files.at("yade.py"), "frictionAngle=0."));
  CHECK_FALSE(contains(files.at("mercurydpm.txt"), "Sliding"));
}
