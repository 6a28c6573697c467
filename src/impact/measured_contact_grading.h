#pragma once

#include <mpi.h>

#include <string>

namespace DiskImpact
{
  struct Parameters;

  /// 'Grade for measured contact': @p parameters with the mesh graded for
  /// the largest contact half-width a_max that an impact on the mesh graded
  /// for Hertz's half-width measures (on @p communicator), with the same
  /// element size at the contact; @p parameters unchanged without it.
  Parameters
  with_mesh_graded_for_measured_contact(const Parameters &parameters,
                                        MPI_Comm          communicator);

  /// The run checks' stand-in before the measurement: the mesh graded for
  /// twice Hertz's half-width with twice the elements (plastic contacts up
  /// to 1000 v_y grow to 1.5 ... 2.2 times Hertz's).
  Parameters
  with_mesh_graded_for_wide_contact(const Parameters &parameters);

  /// The elements across a contact of half-width @p measured with the
  /// element size of @p elements across @p hertz: the nearest even count,
  /// at least 4.
  unsigned int
  elements_across_measured_contact(unsigned int elements,
                                   double       hertz,
                                   double       measured);

  /// One line on the mesh of with_mesh_graded_for_measured_contact()'s
  /// result @p graded.
  std::string
  describe_measured_grading(const Parameters &graded);
} // namespace DiskImpact
