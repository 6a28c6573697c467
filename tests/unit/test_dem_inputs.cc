#include "restitution/dem_inputs.h"

#include <catch2/catch.hpp>

#include <cmath>
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

namespace
{
  /// A steel-like disk's law with the friction coefficient @p mu.
  DiskDemInputs
  disk_law(const double mu)
  {
    DiskDemInputs d{};
    d.radius = 1e-3, d.density = 7850., d.young = 2.1e11, d.poisson = 0.3;
    d.plane = "plane stress", d.speed = 30., d.epsilon = 0.979;
    d.contact_time = 1.5e-6, d.mass = 7850. * M_PI * 1e-6;
    d.pair             = {5e10, 350.};
    d.tangential_ratio = 0.8, d.half_width = 0.1, d.friction = mu;
    return d;
  }
} // namespace

TEST_CASE("A disk's DEM inputs: LAMMPS in 2D with the linear laws", "[dem]")
{
  const auto files = dem_disk_files(disk_law(0.1));
  REQUIRE(files.size() == 1);
  const std::string &lammps = files.at("lammps_2d.txt");
  CHECK(contains(lammps, "density/disc 7850"));
  CHECK(contains(lammps, "nve/sphere disc"));
  CHECK(contains(lammps,
                 "pair_coeff * * hooke 5e+10 350 tangential linear_history "
                 "4e+10 1.0 0.1 damping velocity\n"));
  CHECK(contains(dem_disk_files(disk_law(0.)).at("lammps_2d.txt"),
                 "pair_coeff * * hooke 5e+10 350 tangential linear_nohistory "
                 "0.0 0.0 damping velocity\n"));
}

TEST_CASE("A plastic sphere's DEM inputs add LIGGGHTS' thornton_ning", "[dem]")
{
  CHECK(dem_files(law(0.)).count("liggghts_thornton.txt") == 0);
  auto d              = law(0.2);
  d.limiting_pressure = 3e9, d.yield_speed = 0.2;
  // a_y / R = pi p_y / (2 E*), E* = E / (1 - nu^2).
  const double ratio = M_PI * 3e9 * (1. - 0.09) / (2. * 2.1e11);
  CHECK(liggghts_yield_ratio(d) == Approx(ratio).epsilon(1e-14));
  const std::string text = dem_files(d).at("liggghts_thornton.txt");
  CHECK(
    contains(text,
             "coefficientYieldRatio peratomtype " + ten_digits(ratio) + "\n"));
  CHECK(contains(text, "surfaceEnergy peratomtypepair 1 0\n"));
  CHECK(contains(text, "coefficientFriction peratomtypepair 1 0.2\n"));
  CHECK(contains(text,
                 "pair_style gran model thornton_ning tangential "
                 "history\npair_coeff * *\n"));
}
