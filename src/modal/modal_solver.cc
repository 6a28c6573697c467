#include "modal/modal_solver.h"

#include "base/petsc_check.h"
#include "base/run_error.h"
#include "elasticity/discrete_operator.h"
#include "elasticity/elasticity_operator.h"
#include "material/material.h"
#include "output/atomic_file.h"
#include "output/vtu_record.h"

#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace DiskImpact
{
  using namespace dealii;

  double
  ModalBasis::omega(const unsigned int i) const
  {
    return std::sqrt(std::max(eigenvalues[i], 0.));
  }

  void
  ModalSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal analysis");
    prm.declare_entry("Number of modes",
                      "40",
                      Patterns::Integer(1, 2000),
                      "Number of elastic modes wanted; the rigid-body modes "
                      "come in addition.");
    prm.declare_entry("Torsional modes",
                      "0",
                      Patterns::Integer(0, 2000),
                      "Sphere only: number of torsional modes (azimuthal "
                      "displacement, m = 0) computed beside the spheroidal "
                      "ones, written to torsional_modes.csv; 0: none.");
    prm.declare_entry("Eigensolver tolerance",
                      "1e-10",
                      Patterns::Double(1e-16, 1e-4),
                      "Relative residual tolerance |K x - lambda M x| / "
                      "|lambda| of the eigensolver [-]. The eigenvalue error "
                      "is of the order of its square.");
    prm.leave_subsection();
  }

  void
  ModalSolver::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal analysis");
    n_modes            = prm.get_integer("Number of modes");
    n_torsional        = prm.get_integer("Torsional modes");
    relative_tolerance = prm.get_double("Eigensolver tolerance");
    prm.leave_subsection();
  }

  unsigned int
  ModalSolver::n_elastic_modes() const
  {
    return n_modes;
  }

  void
  ModalSolver::set_n_elastic_modes(const unsigned int n)
  {
    n_modes = n;
  }

  unsigned int
  ModalSolver::n_torsional_modes() const
  {
    return n_torsional;
  }

  double
  ModalSolver::tolerance() const
  {
    return relative_tolerance;
  }

  template <int dim>
  ModalBasis
  ModalSolver::solve(const DiscreteOperator<dim> &op,
                     const unsigned int           n_wanted,
                     const double                 shift) const
  {
    const Mat stiffness = op.stiffness_matrix();
    const Mat mass      = op.mass_matrix();
    check_petsc(MatSetOption(stiffness, MAT_SYMMETRIC, PETSC_TRUE),
                "MatSetOption");
    check_petsc(MatSetOption(mass, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");

    EPS eps;
    check_petsc(EPSCreate(op.get_dof_handler().get_communicator(), &eps),
                "EPSCreate");
    check_petsc(EPSSetOperators(eps, stiffness, mass), "EPSSetOperators");
    check_petsc(EPSSetProblemType(eps, EPS_GHEP), "EPSSetProblemType");
    check_petsc(EPSSetType(eps, EPSKRYLOVSCHUR), "EPSSetType");
    check_petsc(EPSSetDimensions(eps, n_wanted, PETSC_DEFAULT, PETSC_DEFAULT),
                "EPSSetDimensions");
    check_petsc(EPSSetTolerances(eps, relative_tolerance, 1000),
                "EPSSetTolerances");
    check_petsc(EPSSetConvergenceTest(eps, EPS_CONV_REL),
                "EPSSetConvergenceTest");
    check_petsc(EPSSetTarget(eps, shift), "EPSSetTarget");
    check_petsc(EPSSetWhichEigenpairs(eps, EPS_TARGET_REAL),
                "EPSSetWhichEigenpairs");

    // Shift-and-invert: (K - shift M)^{-1} M, the shifted matrix factorized
    // once by MUMPS (M's sparsity pattern is a subset of K's).
    ST  st;
    KSP ksp;
    PC  pc;
    check_petsc(EPSGetST(eps, &st), "EPSGetST");
    check_petsc(STSetType(st, STSINVERT), "STSetType");
    check_petsc(STSetMatStructure(st, SUBSET_NONZERO_PATTERN),
                "STSetMatStructure");
    check_petsc(STGetKSP(st, &ksp), "STGetKSP");
    check_petsc(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
    check_petsc(KSPGetPC(ksp, &pc), "KSPGetPC");
    check_petsc(PCSetType(pc, PCCHOLESKY), "PCSetType");
    check_petsc(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS),
                "PCFactorSetMatSolverType");
    check_petsc(EPSSetFromOptions(eps), "EPSSetFromOptions");

    check_petsc(EPSSolve(eps), "EPSSolve");
    PetscInt n_converged = 0;
    check_petsc(EPSGetConverged(eps, &n_converged), "EPSGetConverged");
    if (n_converged < static_cast<PetscInt>(n_wanted))
      throw RunError("the eigensolver converged " +
                     std::to_string(n_converged) + " of " +
                     std::to_string(n_wanted) + " eigenpairs");

    std::vector<double>                     values(n_converged);
    std::vector<PETScWrappers::MPI::Vector> vectors;
    for (PetscInt i = 0; i < n_converged; ++i)
      {
        vectors.push_back(op.create_vector());
        PetscScalar real, imaginary;
        check_petsc(
          EPSGetEigenpair(eps, i, &real, &imaginary, vectors.back(), nullptr),
          "EPSGetEigenpair");
        values[i] = PetscRealPart(real);
      }
    check_petsc(EPSDestroy(&eps), "EPSDestroy");

    // SLEPc may return more pairs than asked for, not always sorted.
    std::vector<unsigned int> order(n_converged);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](unsigned int a, unsigned int b) {
      return values[a] < values[b];
    });
    ModalBasis basis;
    for (unsigned int i = 0; i < n_wanted; ++i)
      {
        basis.eigenvalues.push_back(values[order[i]]);
        basis.modes.push_back(std::move(vectors[order[i]]));
        op.get_constraints().distribute(basis.modes.back());
      }
    return basis;
  }

  template ModalBasis
  ModalSolver::solve(const DiscreteOperator<2> &, unsigned int, double) const;
  template ModalBasis
  ModalSolver::solve(const DiscreteOperator<3> &, unsigned int, double) const;

  template <int dim>
  double
  assemble_eigenproblem(ElasticityOperator<dim> &op,
                        const Material          &material,
                        const double             radius,
                        TimerOutput             &timer)
  {
    {
      TimerOutput::Scope scope(timer, "assembly");
      op.assemble(material);
    }
    const double scale = std::pow(material.transverse_wave_speed() / radius, 2);
    op.move_constrained_eigenvalues(1e10 * scale);
    return scale;
  }

  template double
  assemble_eigenproblem(ElasticityOperator<2> &,
                        const Material &,
                        double,
                        TimerOutput &);
  template double
  assemble_eigenproblem(ElasticityOperator<3> &,
                        const Material &,
                        double,
                        TimerOutput &);

  template <int dim>
  void
  write_mode_shapes(const DiscreteOperator<dim>     &op,
                    const ModalBasis                &basis,
                    const std::vector<unsigned int> &indices,
                    const std::string               &directory)
  {
    // One file, one vector field per mode ("mode_007"), so the mesh and the
    // curved patches are built once.
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
                                            vector_field(dim,
                   DataComponentInterpretation::component_is_part_of_vector);
    DataOut<dim>                            data_out;
    std::vector<PETScWrappers::MPI::Vector> ghosted;
    data_out.attach_dof_handler(op.get_dof_handler());
    for (const unsigned int index : indices)
      ghosted.push_back(op.create_ghosted(basis.modes[index]));
    for (unsigned int i = 0; i < indices.size(); ++i)
      data_out.add_data_vector(
        ghosted[i],
        std::vector<std::string>(dim,
                                 "mode_" +
                                   Utilities::int_to_string(indices[i], 3)),
        DataOut<dim>::type_dof_data,
        vector_field);
    data_out.build_patches(op.get_mapping(),
                           op.degree(),
                           DataOut<dim>::curved_inner_cells);
    DataOutBase::VtkFlags flags;
    flags.compression_level =
      DataOutBase::VtkFlags::ZlibCompressionLevel::best_speed;
    data_out.set_flags(flags);
    const MPI_Comm    communicator = op.get_dof_handler().get_communicator();
    const std::string name =
      write_vtu_record(data_out, directory, "modes", 0, communicator);
    on_root(communicator, [&]() {
      write_atomically(directory + "/modes.pvd", [&](std::ostream &out) {
        DataOutBase::write_pvd_record(out, {{0., name}});
      });
    });
  }

  template void
  write_mode_shapes(const DiscreteOperator<2> &,
                    const ModalBasis &,
                    const std::vector<unsigned int> &,
                    const std::string &);
  template void
  write_mode_shapes(const DiscreteOperator<3> &,
                    const ModalBasis &,
                    const std::vector<unsigned int> &,
                    const std::string &);
} // namespace DiskImpact
