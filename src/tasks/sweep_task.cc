#include "tasks/sweep_task.h"

#include "csv_table.h"
#include "parameters.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace DiskImpact
{
  using namespace dealii;

  void
  run_sweep(const Parameters &parameters, MPI_Comm communicator)
  {
    const bool root = Utilities::MPI::this_mpi_process(communicator) == 0;
    ConditionalOStream  pcout(std::cout, root);
    std::vector<double> ratios = parameters.impact.poisson_ratios();
    if (ratios.empty())
      ratios.push_back(std::nan(""));

    CsvTable table({"velocity",
                    "poisson_ratio",
                    "epsilon",
                    "epsilon_error",
                    "contact_time",
                    "delta_max",
                    "force_max",
                    "energy_error",
                    "poisson_ratio_2d",
                    "epsilon_coarse",
                    "steps",
                    "n_dofs"});
    pcout << "   v/c      nu    nu2       epsilon     error      contact "
             "time  energy err.\n";
    for (const double nu : ratios)
      for (const double v : parameters.impact.velocities())
        {
          Parameters point = parameters;
          if (!std::isnan(nu))
            point.material = parameters.material.with_poisson_ratio(nu);
          point.impact.set_velocity(v);
          ImpactSummary s      = point.impact.run(point, communicator, false);
          double        coarse = std::nan(""), error = std::nan("");
          if (parameters.impact.estimate_errors())
            {
              Parameters finer = point;
              finer.geometry.set_global_refinements(
                point.geometry.global_refinements() + 1);
              finer.impact          = point.impact.refined();
              finer.time_integrator = point.time_integrator.refined();
              finer.contact.set_penalty_factor(4. *
                                               point.contact.penalty_factor());
              coarse = s.epsilon;
              s      = finer.impact.run(finer, communicator, false);
              error  = std::abs(s.epsilon - coarse);
            }
          const double nu_used =
            std::isnan(nu) ? point.material.poisson_ratio() : nu;
          table.start_row();
          for (const double value : {v,
                                     nu_used,
                                     s.epsilon,
                                     error,
                                     s.contact_time,
                                     s.delta_max,
                                     s.force_max,
                                     s.energy_error,
                                     point.material.in_plane_poisson_ratio(),
                                     coarse})
            table.add(value);
          table.add(s.steps);
          table.add(s.n_dofs);
          if (root)
            table.write(parameters.run.output_directory + "/restitution.csv");
          std::ostringstream line;
          line << std::fixed << std::setprecision(4) << std::setw(7) << v
               << std::setw(8) << nu_used << std::setw(7)
               << point.material.in_plane_poisson_ratio()
               << std::setprecision(7) << std::setw(12) << s.epsilon
               << std::scientific << std::setprecision(1) << std::setw(10)
               << error << std::fixed << std::setprecision(4) << std::setw(12)
               << s.contact_time << std::scientific << std::setprecision(1)
               << std::setw(11) << s.energy_error << '\n';
          pcout << line.str() << std::flush;
        }
  }
} // namespace DiskImpact
