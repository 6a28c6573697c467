#pragma once

#include <deal.II/base/parameter_handler.h>

#include <deal.II/grid/tria.h>

#include <mpi.h>

#include <limits>
#include <vector>

namespace DiskImpact
{
  struct Parameters;

  /// One converged quasistatic contact state, lengths in units of R.
  struct ContactLawPoint
  {
    /// P / (pi E2 R) (disk), P / (pi E* R^2) (sphere)
    double       load              = 0.;
    double       delta_com         = 0.; ///< approach of the centre of mass
    double       delta_diameter    = 0.; ///< shortening of the axial diameter
    double       half_width        = 0.; ///< a / R from the pressure moments
    double       penetration       = 0.; ///< deepest penetration / R
    double       force_balance     = 0.; ///< int p ds / P - 1
    double       h_contact         = 0.; ///< smallest edge face / R
    unsigned int n_dofs            = 0;
    unsigned int newton_iterations = 0;
    /// The largest von Mises stress over Hertz's peak pressure p0, its
    /// depth below the contact point and its distance from the axis (over
    /// Hertz's a): the body first yields where it reaches Y.
    double von_mises_max = 0., von_mises_depth = 0., von_mises_offset = 0.;
  };

  /**
   * Task 'quasistatic contact': a half disk (symmetric about the impact
   * axis) or a sphere pressed on the wall by a uniform body force of total
   * P (Gerl & Zippelius 1999, section 5: the quasistatic picture of the body
   * being decelerated), for a list of loads, against
   * Reference::WallContactTheory. Per load: a mesh graded toward the contact
   * point so the elements across the whole Hertz half-width are small, then
   * Newton's method with a backtracking line search on the penalty contact
   * problem. Writes contact_law.csv, pressure_profile.csv (two
   * dimensions) and the deformed states (contact.pvd). A disk of finite
   * thickness in 3D is its quarter y >= 0, 0 <= z <= H/2 (P per unit
   * thickness as in 2D), the sphere in 3D its quarter y >= 0, z >= 0. An
   * elastic-plastic body is loaded to the
   * largest of the loads and unloaded instead (QuasistaticIndentation).
   */
  class QuasistaticContact
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    void
    run(const Parameters &parameters, MPI_Comm communicator) const;

    /// The largest of the 'Loads'.
    double
    largest_load() const;
    /// 'Elements across contact'.
    unsigned int
    elements_across() const
    {
      return elements_across_contact;
    }
    /// 'Graded mesh = conforming'.
    bool
    conforming_mesh() const
    {
      return conforming;
    }

    /// The mesh for @p load, graded toward the contact point (with a
    /// partner body both bodies', for the pair's Hertz half-width; a disk
    /// in 3D: its section graded without hanging nodes, extruded through
    /// layers graded toward the face); throws an InputError if it would
    /// exceed about @p max_cells cells.
    template <int dim>
    void
    create_mesh(
      const Parameters           &parameters,
      double                      load,
      dealii::Triangulation<dim> &triangulation,
      double max_cells = std::numeric_limits<double>::infinity()) const;

  private:
    /// run() for an elastic body on the wall, in two or three dimensions.
    template <int dim>
    void
    run_elastic(const Parameters &parameters, MPI_Comm communicator) const;

    /// run() with a partner body (QuasistaticPair): contact_law.csv with
    /// the approach of the centres, each body's share and the constants.
    void
    run_pair(const Parameters &parameters, MPI_Comm communicator) const;

    std::vector<double> loads;
    unsigned int        elements_across_contact = 16;
    bool                conforming              = false;
    double              grading                 = 0.3;
    double              newton_tolerance        = 1e-10;
    unsigned int        max_newton_iterations   = 30;
    unsigned int        indentation_steps       = 20;
  };
} // namespace DiskImpact
