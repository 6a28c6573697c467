#pragma once

// The disks of the unit tests that need a mesh.

#include "body/geometry.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace DiskImpact
{
  /// The disk of 'Domain' @p domain with @p global_refinements and
  /// @p contact_refinements (subsection Geometry).
  inline BodyGeometry
  disk_geometry(const std::string &domain,
                const unsigned int global_refinements,
                const unsigned int contact_refinements = 0)
  {
    dealii::ParameterHandler prm;
    BodyGeometry::declare_parameters(prm);
    prm.enter_subsection("Geometry");
    prm.set("Domain", domain);
    prm.set("Global refinements", std::to_string(global_refinements));
    prm.set("Contact refinements", std::to_string(contact_refinements));
    prm.leave_subsection();
    BodyGeometry geometry;
    geometry.parse_parameters(prm);
    return geometry;
  }

  /// The half disk with @p global_refinements and @p contact_refinements.
  inline BodyGeometry
  half_disk(const unsigned int global_refinements,
            const unsigned int contact_refinements = 0)
  {
    return disk_geometry("half disk", global_refinements, contact_refinements);
  }
} // namespace DiskImpact
