#include "elasticity/elasticity_operator.h"

#include "body/geometry.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor_function.h>

#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <limits>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// Whether @p cell belongs to the body of material id @p body (every
    /// cell does if @p body is invalid_material_id).
    template <typename Cell>
    bool
    on_body(const Cell &cell, const types::material_id body)
    {
      return body == numbers::invalid_material_id ||
             cell->material_id() == body;
    }

    /// Copy the lower triangle of the square @p matrix onto its upper one.
    void
    mirror_lower_triangle(FullMatrix<double> &matrix)
    {
      for (unsigned int i = 0; i < matrix.m(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          matrix(j, i) = matrix(i, j);
    }
  } // namespace

  void
  FiniteElementParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    prm.declare_entry("Degree",
                      "2",
                      Patterns::Integer(1, 6),
                      "Polynomial degree k of the vector Q_k elements; the "
                      "curved boundary is mapped with degree k as well.");
    prm.leave_subsection();
  }

  void
  FiniteElementParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    degree = prm.get_integer("Degree");
    prm.leave_subsection();
  }

  template <int dim>
  ElasticityOperator<dim>::ElasticityOperator(const unsigned int degree)
      : DiscreteOperator<dim>(degree)
  {
  }

  template <int dim>
  void
  ElasticityOperator<dim>::setup(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const BodyGeometry                              &geometry,
    const bool                                       with_tangent,
    const std::vector<Point<dim>>                   &axial_pins)
  {
    point_states.clear();
    section = Section<dim>(geometry.is_axisymmetric());
    fe      = std::make_unique<FESystem<dim>>(FE_Q<dim>(fe_degree), dim);
    this->distribute_dofs(triangulation, *fe);
    constraints.clear();
    constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    {
      AffineConstraints<double> hanging(constraints);
      hanging.close();
      this->conform_mapping_to_constraints(hanging);
    }
    // The symmetry conditions u_y = 0 on y = 0 and, in 3D, u_z = 0 on
    // z = 0.
    for (unsigned int d = 1; d < dim; ++d)
      if (d == 1 ? geometry.has_symmetry_boundary() :
                   geometry.has_symmetry_plane_z())
        {
          std::vector<bool> component(dim, false);
          component[d] = true;
          VectorTools::interpolate_boundary_values(
            *mapping,
            dof_handler,
            d == 1 ? BoundaryIds::symmetry : BoundaryIds::symmetry_z,
            Functions::ZeroFunction<dim>(dim),
            constraints,
            ComponentMask(component));
        }
    // A disk in 3D with held faces: u_z = 0 on z = +-H/2.
    if (dim == 3 && geometry.faces_held())
      {
        std::vector<bool> z_only(dim, false);
        z_only[dim - 1] = true;
        VectorTools::interpolate_boundary_values(*mapping,
                                                 dof_handler,
                                                 BoundaryIds::flat_faces,
                                                 Functions::ZeroFunction<dim>(
                                                   dim),
                                                 constraints,
                                                 ComponentMask(z_only));
      }
    pin_axial_displacement(axial_pins);
    constraints.close();
    massless_dofs      = IndexSet(dof_handler.n_dofs());
    redistributed_dofs = IndexSet(dof_handler.n_dofs());

    // K couples the two displacement components, M does not: M gets its
    // own pattern, half as many entries (its products dominate the
    // eigensolver's time). M's pattern is a subset of K's.
    const MPI_Comm               comm = triangulation.get_communicator();
    Table<2, DoFTools::Coupling> all_components(dim, dim),
      same_component(dim, dim);
    all_components.fill(DoFTools::always);
    same_component.fill(DoFTools::none);
    for (unsigned int d = 0; d < dim; ++d)
      same_component(d, d) = DoFTools::always;
    auto make_matrix = [&](const Table<2, DoFTools::Coupling> &coupling,
                           PETScWrappers::MPI::SparseMatrix   &matrix) {
      DynamicSparsityPattern dsp(relevant_dofs);
      DoFTools::make_sparsity_pattern(
        dof_handler, coupling, dsp, constraints, false);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 owned_dofs,
                                                 comm,
                                                 relevant_dofs);
      matrix.reinit(owned_dofs, owned_dofs, dsp, comm);
    };
    make_matrix(all_components, stiffness);
    make_matrix(same_component, mass);
    // The tangent has K's pattern: a copy of its structure.
    if (with_tangent)
      tangent.reinit(stiffness);
  }

  template <int dim>
  void
  ElasticityOperator<dim>::set_massless_edge_zone(const Point<dim> &point,
                                                  const double      radius)
  {
    std::vector<types::global_dof_index> face_dofs(fe->n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == BoundaryIds::curved &&
              cell->face(f)->center().distance(point) < radius)
            {
              cell->face(f)->get_dof_indices(face_dofs);
              for (const auto dof : face_dofs)
                if (!constraints.is_constrained(dof))
                  massless_dofs.add_index(dof);
            }
    massless_dofs.compress();
    // A hanging node's mass, left in place, would reach the massless DoFs
    // it depends on through its constraint: it moves too.
    redistributed_dofs = massless_dofs;
    for (const auto &line : constraints.get_lines())
      for (const auto &entry : line.entries)
        if (massless_dofs.is_element(entry.first))
          redistributed_dofs.add_index(line.index);
    redistributed_dofs.compress();
  }

  template <int dim>
  unsigned int
  ElasticityOperator<dim>::n_massless_dofs() const
  {
    return Utilities::MPI::sum(static_cast<unsigned int>(
                                 (massless_dofs & owned_dofs).n_elements()),
                               dof_handler.get_communicator());
  }

  template <int dim>
  std::vector<types::global_dof_index>
  ElasticityOperator<dim>::massless_dof_list() const
  {
    std::vector<types::global_dof_index> local;
    for (const auto dof : massless_dofs)
      if (owned_dofs.is_element(dof))
        local.push_back(dof);
    std::vector<types::global_dof_index> all;
    for (const auto &part :
         Utilities::MPI::all_gather(dof_handler.get_communicator(), local))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    return all;
  }

  template <int dim>
  FullMatrix<double>
  ElasticityOperator<dim>::stiffness_block(
    const std::vector<types::global_dof_index> &dofs) const
  {
    // (row, column, value) of this rank's rows, then everyone's.
    std::vector<double> local;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (owned_dofs.is_element(dofs[i]))
        for (auto entry = stiffness.begin(dofs[i]);
             entry != stiffness.end(dofs[i]);
             ++entry)
          {
            const auto j =
              std::lower_bound(dofs.begin(), dofs.end(), entry->column()) -
              dofs.begin();
            if (j < static_cast<long>(dofs.size()) &&
                dofs[j] == entry->column())
              local.insert(local.end(),
                           {static_cast<double>(i),
                            static_cast<double>(j),
                            entry->value()});
          }
    FullMatrix<double> block(dofs.size(), dofs.size());
    for (const auto &part :
         Utilities::MPI::all_gather(dof_handler.get_communicator(), local))
      for (std::size_t k = 0; k < part.size(); k += 3)
        block(static_cast<unsigned int>(part[k]),
              static_cast<unsigned int>(part[k + 1])) = part[k + 2];
    return block;
  }

  template <int dim>
  void
  ElasticityOperator<dim>::redistribute_cell_mass(
    const std::vector<types::global_dof_index> &dof_indices,
    FullMatrix<double>                         &cell_mass) const
  {
    // source[i]: the cell DoF whose value DoF i takes in the mass form.
    const unsigned int        n = dof_indices.size();
    std::vector<unsigned int> source(n);
    bool                      any_moved = false;
    for (unsigned int i = 0; i < n; ++i)
      {
        source[i] = i;
        if (!redistributed_dofs.is_element(dof_indices[i]))
          continue;
        any_moved             = true;
        const auto  component = fe->system_to_component_index(i).first;
        const auto &point     = fe->unit_support_point(i);
        double      best      = std::numeric_limits<double>::max();
        for (unsigned int j = 0; j < n; ++j)
          if (fe->system_to_component_index(j).first == component &&
              !redistributed_dofs.is_element(dof_indices[j]) &&
              point.distance(fe->unit_support_point(j)) < best)
            {
              best      = point.distance(fe->unit_support_point(j));
              source[i] = j;
            }
        Assert(source[i] != i, ExcInternalError());
      }
    if (!any_moved)
      return;
    // (Pi^T M Pi)(k, l) = sum over a, b with source[a] = k, source[b] = l.
    FullMatrix<double> redistributed(n, n);
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int b = 0; b < n; ++b)
        redistributed(source[a], source[b]) += cell_mass(a, b);
    cell_mass = redistributed;
  }

  template <int dim>
  PETScWrappers::MPI::Vector
  ElasticityOperator<dim>::mass_functional(
    const PETScWrappers::MPI::Vector &y) const
  {
    auto y0 = y, my = this->create_vector();
    constraints.set_zero(y0);
    mass.vmult(my, y0);
    constraints.set_zero(my);
    return my;
  }

  template <int dim>
  void
  ElasticityOperator<dim>::assemble(const Material &material)
  {
    assemble(std::vector<Material>{material});
  }

  template <int dim>
  void
  ElasticityOperator<dim>::assemble(const std::vector<Material> &materials)
  {
    Assert(!materials.empty(), ExcInternalError());
    const QGauss<dim>  quadrature(fe_degree + 1);
    FEValues<dim>      fe_values(*mapping,
                            *fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    const unsigned int dofs_per_cell = fe->n_dofs_per_cell();
    FullMatrix<double> cell_mass(dofs_per_cell, dofs_per_cell);
    FullMatrix<double> cell_stiffness(dofs_per_cell, dofs_per_cell);
    FullMatrix<double> cell_damping(dofs_per_cell, dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    const FEValuesExtractors::Vector     displacement(0);

    // Axisymmetric: the hoop strain h adds lambda (tr eps h' + h tr eps')
    // + (lambda + 2 mu) h h' to eps : C : eps' (and tau times that to the
    // Kelvin-Voigt form; the constants are 3D, as in plane strain).
    auto hoop_energy = [](const Material &material,
                          const double    tr_i,
                          const double    h_i,
                          const double    tr_j,
                          const double    h_j) {
      return material.lame_lambda() * (tr_i * h_j + h_i * tr_j) +
             (material.lame_lambda() + 2. * material.shear_modulus()) * h_i *
               h_j;
    };
    // K and D from each body's constitutive law at the quadrature points,
    // whose states are kept from one assembly to the next.
    laws.clear();
    for (const Material &material : materials)
      laws.push_back(make_constitutive_law<dim>(material));
    with_damping = std::any_of(laws.begin(), laws.end(), [](const auto &law) {
      return law->is_viscous();
    });
    if (with_damping)
      {
        damping.reinit(stiffness);
        damping = 0.;
      }

    std::vector<SymmetricTensor<2, dim>> eps(dofs_per_cell);
    std::vector<double> value(dofs_per_cell), hoop(dofs_per_cell),
      trace(dofs_per_cell);
    // Each shape function of the vector element is nonzero in one
    // component only: the mass form couples equal components alone.
    std::vector<unsigned int> component(dofs_per_cell);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      component[i] = fe->system_to_component_index(i).first;

    mass      = 0.;
    stiffness = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // One material for every cell (a mesh file's cells carry its
          // physical tags as material ids), or each body's: material id 0,
          // or 1 for a collision partner.
          const unsigned int which =
            materials.size() == 1 ? 0 : cell->material_id();
          AssertIndexRange(which, materials.size());
          const Material             &material = materials[which];
          const ConstitutiveLaw<dim> &law      = *laws[which];
          const double                rho      = material.density();
          const double                tau      = material.relaxation_time();
          if (!point_states.try_get_data(cell))
            law.initialize_states(point_states, cell, quadrature.size());
          const auto states = point_states.get_data(cell);
          fe_values.reinit(cell);
          cell_mass      = 0.;
          cell_stiffness = 0.;
          if (with_damping)
            cell_damping = 0.;
          // The three forms are symmetric: the lower triangle, mirrored
          // below.
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const Point<dim> &x = fe_values.quadrature_point(q);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  const Tensor<1, dim> phi =
                    fe_values[displacement].value(i, q);
                  value[i] = phi[component[i]];
                  eps[i]   = fe_values[displacement].symmetric_gradient(i, q);
                  hoop[i]  = section.hoop_strain(phi, x);
                  trace[i] = dealii::trace(eps[i]);
                }
              const double dx = fe_values.JxW(q) * section.measure(x);
              const SymmetricTensor<4, dim> c =
                law.stiffness_tangent(*states[q]);
              const SymmetricTensor<4, dim> d =
                with_damping ? law.damping_tangent(*states[q]) :
                               SymmetricTensor<4, dim>();
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  const SymmetricTensor<2, dim> c_eps_i = c * eps[i];
                  const SymmetricTensor<2, dim> d_eps_i =
                    with_damping ? d * eps[i] : SymmetricTensor<2, dim>();
                  for (unsigned int j = 0; j <= i; ++j)
                    {
                      const double h_ij = section.is_axisymmetric() ?
                                            hoop_energy(material,
                                                        trace[i],
                                                        hoop[i],
                                                        trace[j],
                                                        hoop[j]) :
                                            0.;
                      if (component[i] == component[j])
                        cell_mass(i, j) += rho * value[i] * value[j] * dx;
                      cell_stiffness(i, j) += (c_eps_i * eps[j] + h_ij) * dx;
                      if (with_damping)
                        cell_damping(i, j) +=
                          (d_eps_i * eps[j] + tau * h_ij) * dx;
                    }
                }
            }
          mirror_lower_triangle(cell_mass);
          mirror_lower_triangle(cell_stiffness);
          if (with_damping)
            mirror_lower_triangle(cell_damping);
          cell->get_dof_indices(dof_indices);
          redistribute_cell_mass(dof_indices, cell_mass);
          constraints.distribute_local_to_global(cell_mass, dof_indices, mass);
          constraints.distribute_local_to_global(cell_stiffness,
                                                 dof_indices,
                                                 stiffness);
          if (with_damping)
            constraints.distribute_local_to_global(cell_damping,
                                                   dof_indices,
                                                   damping);
        }
    mass.compress(VectorOperation::add);
    stiffness.compress(VectorOperation::add);
    if (with_damping)
      damping.compress(VectorOperation::add);
  }

  template <int dim>
  const ConstitutiveLaw<dim> &
  ElasticityOperator<dim>::constitutive_law(const unsigned int body) const
  {
    AssertIndexRange(body, laws.size());
    return *laws[body];
  }

  template <int dim>
  QuadraturePointStates<dim> &
  ElasticityOperator<dim>::quadrature_point_states()
  {
    return point_states;
  }

  template <int dim>
  bool
  ElasticityOperator<dim>::has_damping() const
  {
    return with_damping;
  }

  template <int dim>
  const PETScWrappers::MPI::SparseMatrix &
  ElasticityOperator<dim>::damping_matrix() const
  {
    return damping;
  }

  template <int dim>
  void
  ElasticityOperator<dim>::assemble_body_force(
    const Tensor<1, dim>       &force_per_area,
    PETScWrappers::MPI::Vector &f,
    const types::material_id    body) const
  {
    assemble_body_force(ConstantTensorFunction<1, dim>(force_per_area),
                        f,
                        body);
  }

  template <int dim>
  void
  ElasticityOperator<dim>::assemble_body_force(
    const TensorFunction<1, dim> &force_per_area,
    PETScWrappers::MPI::Vector   &f,
    const types::material_id      body) const
  {
    const QGauss<dim>                    quadrature(fe_degree + 1);
    FEValues<dim>                        fe_values(*mapping,
                            *fe,
                            quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    const unsigned int                   dofs_per_cell = fe->n_dofs_per_cell();
    Vector<double>                       cell_f(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    const FEValuesExtractors::Vector     displacement(0);
    f = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && on_body(cell, body))
        {
          fe_values.reinit(cell);
          cell_f = 0.;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const Point<dim>    &x     = fe_values.quadrature_point(q);
              const Tensor<1, dim> force = force_per_area.value(x);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                cell_f(i) += force * fe_values[displacement].value(i, q) *
                             fe_values.JxW(q) * section.measure(x);
            }
          cell->get_dof_indices(dof_indices);
          constraints.distribute_local_to_global(cell_f, dof_indices, f);
        }
    f.compress(VectorOperation::add);
  }

  template <int dim>
  void
  ElasticityOperator<dim>::pin_axial_displacement(
    const std::vector<Point<dim>> &pins)
  {
    for (const Point<dim> &pin : pins)
      {
        const double tolerance = 1e-10 * (1. + pin.norm());
        double       found     = 0.;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            for (const unsigned int v : cell->vertex_indices())
              if (cell->vertex(v).distance(pin) < tolerance)
                {
                  const auto dof = cell->vertex_dof_index(v, 0);
                  if (!constraints.is_constrained(dof))
                    constraints.add_line(dof);
                  found = 1.;
                }
        AssertThrow(Utilities::MPI::max(found, dof_handler.get_communicator()) >
                      0.,
                    ExcMessage("setup: no mesh vertex at an axial pin"));
      }
  }

  template <int dim>
  double
  ElasticityOperator<dim>::volume(const types::material_id body) const
  {
    const QGauss<dim> quadrature(fe_degree + 1);
    FEValues<dim>     fe_values(*mapping,
                            *fe,
                            quadrature,
                            update_quadrature_points | update_JxW_values);
    double            sum = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && on_body(cell, body))
        {
          fe_values.reinit(cell);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            sum +=
              fe_values.JxW(q) * section.measure(fe_values.quadrature_point(q));
        }
    return Utilities::MPI::sum(sum, dof_handler.get_communicator());
  }

  template <int dim>
  Tensor<1, dim>
  ElasticityOperator<dim>::mean_displacement(
    const PETScWrappers::MPI::Vector &ghosted_u,
    const types::material_id          body) const
  {
    const QGauss<dim>           quadrature(fe_degree + 1);
    FEValues<dim>               fe_values(*mapping,
                            *fe,
                            quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    std::vector<Tensor<1, dim>> u(quadrature.size());
    Tensor<1, dim>              integral;
    double                      volume = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && on_body(cell, body))
        {
          fe_values.reinit(cell);
          fe_values[FEValuesExtractors::Vector(0)].get_function_values(
            ghosted_u, u);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const double dv = fe_values.JxW(q) *
                                section.measure(fe_values.quadrature_point(q));
              integral += u[q] * dv;
              volume += dv;
            }
        }
    // On a body of revolution the radial displacements cancel in the 3D
    // mean: the centre of mass moves along the axis only.
    if (section.is_axisymmetric())
      integral[1] = 0.;
    const MPI_Comm comm = dof_handler.get_communicator();
    return Utilities::MPI::sum(integral, comm) /
           Utilities::MPI::sum(volume, comm);
  }

  template <int dim>
  Tensor<1, dim>
  ElasticityOperator<dim>::vertex_displacement(
    const PETScWrappers::MPI::Vector &ghosted_u,
    const Point<dim>                 &vertex,
    const types::material_id          body) const
  {
    // Each rank that owns a cell at the vertex contributes once.
    const double   tolerance = 1e-10 * (1. + vertex.norm());
    Tensor<1, dim> u;
    double         found = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && on_body(cell, body) && found == 0.)
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v).distance(vertex) < tolerance)
            {
              for (unsigned int c = 0; c < dim; ++c)
                u[c] = ghosted_u(cell->vertex_dof_index(v, c));
              found = 1.;
              break;
            }
    const MPI_Comm comm    = dof_handler.get_communicator();
    const double   n_found = Utilities::MPI::sum(found, comm);
    AssertThrow(n_found > 0.,
                ExcMessage("vertex_displacement: no mesh vertex at the point"));
    return Utilities::MPI::sum(u, comm) / n_found;
  }

  template <int dim>
  PETScWrappers::MPI::SparseMatrix &
  ElasticityOperator<dim>::tangent_reset_to_stiffness()
  {
    tangent.copy_from(stiffness);
    return tangent;
  }

  template <int dim>
  const PETScWrappers::MPI::SparseMatrix &
  ElasticityOperator<dim>::tangent_matrix() const
  {
    return tangent;
  }

  template <int dim>
  const Section<dim> &
  ElasticityOperator<dim>::get_section() const
  {
    return section;
  }

  template class ElasticityOperator<2>;
  template class ElasticityOperator<3>;
} // namespace DiskImpact
