#pragma once

// The half disk of the unit tests that need a mesh.

#include "body/geometry.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace DiskImpact
{
  /// The half disk with @p global_refinements and @p contact_refinements
  /// (subsection Geometry).
  inline BodyGeometry
  half_disk(const unsigned int global_refinements,
            const unsigned int contact_refinements = 0)
  {
    dealii::ParameterHandler prm;
    BodyGeometry::declare_parameters(prm);
    prm.enter_subsection("Geometry");
    prm.set("Domain", "half disk");
    prm.set("Global refinements", std::to_string(global_refinements));
    prm.set("Contact refinements", std::to_string(contact_refinements));
    prm.leave_subsection();
    BodyGeometry geometry;
    geometry.parse_parameters(prm);
    return geometry;
  }
} // namespace DiskImpact
