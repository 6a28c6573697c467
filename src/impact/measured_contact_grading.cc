#include "impact/measured_contact_grading.h"

#include "base/run_error.h"
#include "impact/impact_mesh.h"
#include "impact/impact_simulation.h"
#include "run/parameters.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace DiskImpact
{
  namespace
  {
    /// @p parameters with the mesh graded for @p half_width [R].
    Parameters
    graded_for(const Parameters &parameters, const double half_width)
    {
      const double hertz =
        largest_half_width(parameters) / parameters.geometry.radius();
      Parameters graded = parameters;
      graded.impact     = parameters.impact.with_mesh_graded_for(
        half_width,
        elements_across_measured_contact(
          parameters.impact.elements_across_contact(), hertz, half_width),
        parameters.impact.grading(),
        parameters.impact.conforming_mesh());
      return graded;
    }
  } // namespace

  unsigned int
  elements_across_measured_contact(const unsigned int elements,
                                   const double       hertz,
                                   const double       measured)
  {
    const long half = std::lround(0.5 * elements * measured / hertz);
    return 2 * static_cast<unsigned int>(std::max(2L, half));
  }

  Parameters
  with_mesh_graded_for_measured_contact(const Parameters &parameters,
                                        MPI_Comm          communicator)
  {
    if (!parameters.impact.grades_for_measured_contact())
      return parameters;
    // The first impact grades for Hertz's half-width: the flag is only
    // read here.
    const double measured =
      run_impact(parameters, communicator, false).contact_half_width_max;
    if (!(measured > 0.))
      throw RunError("'Grade for measured contact': the impact on the mesh "
                     "graded for Hertz's half-width made no contact");
    return graded_for(parameters, std::min(measured, 1.));
  }

  Parameters
  with_mesh_graded_for_wide_contact(const Parameters &parameters)
  {
    if (!parameters.impact.grades_for_measured_contact())
      return parameters;
    return graded_for(parameters,
                      std::min(2. * largest_half_width(parameters) /
                                 parameters.geometry.radius(),
                               1.));
  }

  std::string
  describe_measured_grading(const Parameters &graded)
  {
    const double hertz = largest_half_width(graded) / graded.geometry.radius();
    std::ostringstream line;
    line.precision(4);
    line << "Mesh graded for the measured contact half-width "
         << graded.impact.graded_half_width() << " R ("
         << graded.impact.graded_half_width() / hertz << " times Hertz's), "
         << graded.impact.elements_across_contact() << " elements across it";
    return line.str();
  }
} // namespace DiskImpact
