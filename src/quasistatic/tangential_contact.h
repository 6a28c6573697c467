#pragma once

#include <deal.II/base/parameter_handler.h>

#include <deal.II/grid/tria.h>

#include <mpi.h>

#include <limits>
#include <vector>

namespace DiskImpact
{
  struct Parameters;

  /**
   * Task 'tangential contact': the tangential compliance of the contact
   * (Cattaneo 1938, Mindlin 1949). The whole disk or the half sphere is
   * pressed on the wall by a uniform body force of total P with the wall
   * frictionless (Hertz's state), then, with Coulomb friction on, pulled
   * along the wall by a body force of total Q = q mu P for each q of
   * 'Tangential loads' in turn (each step starting from the last one's
   * stick and slip). The tangential body force varies linearly with the
   * height above the wall so that it exerts no moment about the contact
   * point: the body is sheared, not rolled. Each state solves K u = f +
   * E_C P(u_C) exactly on the contact DoFs C, with the body's rigid
   * motions as unknowns held by the contact alone (docs/theory/
   * tangential-compliance.md). Writes tangential_law.csv.
   */
  class TangentialContact
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

    /// The mesh for @p load: the geometry's, graded toward the contact
    /// point for Hertz's half-width; throws an InputError if it would
    /// exceed about @p max_cells cells.
    template <int dim>
    void
    create_mesh(
      const Parameters           &parameters,
      double                      load,
      dealii::Triangulation<dim> &triangulation,
      double max_cells = std::numeric_limits<double>::infinity()) const;

    const std::vector<double> &
    tangential_loads() const;
    /// 'Tangential load step': the largest step of Q / (mu P).
    double
    tangential_load_step() const;
    double
    newton_tolerance() const;
    unsigned int
    max_newton_iterations() const;

  private:
    template <int dim>
    void
    run_in(const Parameters &parameters, MPI_Comm communicator) const;

    std::vector<double> loads;
    std::vector<double> tangential_load_steps;
    unsigned int        elements_across_contact = 8;
    double              grading                 = 0.3;
    double              load_step               = 0.05;
    double              tolerance               = 1e-10;
    unsigned int        max_iterations          = 300;
  };
} // namespace DiskImpact
