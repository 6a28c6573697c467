#include "output/revolved_view.h"

#include "base/input_error.h"

#include <deal.II/grid/reference_cell.h>

#include <algorithm>
#include <cmath>

namespace DiskImpact
{
  using namespace dealii;

  namespace
  {
    /// The coordinates of point @p j of a meridian patch: stored after the
    /// data rows, or bilinear between the vertices (lexicographic order).
    Point<2>
    patch_point(const DataOutBase::Patch<2, 2> &patch,
                const unsigned int              j,
                const unsigned int              n_data)
    {
      if (patch.points_are_available)
        return Point<2>(patch.data(n_data, j), patch.data(n_data + 1, j));
      const unsigned int n  = patch.n_subdivisions;
      const double       sx = double(j % (n + 1)) / n;
      const double       sy = double(j / (n + 1)) / n;
      return (1. - sx) * (1. - sy) * patch.vertices[0] +
             sx * (1. - sy) * patch.vertices[1] +
             (1. - sx) * sy * patch.vertices[2] + sx * sy * patch.vertices[3];
    }

    /// The point indices of edge @p e of a patch with @p n subdivisions, in
    /// deal.II's face numbering (0: x = 0, 1: x = 1, 2: y = 0, 3: y = 1).
    std::vector<unsigned int>
    edge_points(const unsigned int e, const unsigned int n)
    {
      std::vector<unsigned int> points;
      for (unsigned int k = 0; k <= n; ++k)
        switch (e)
          {
            case 0:
              points.push_back(k * (n + 1));
              break;
            case 1:
              points.push_back(k * (n + 1) + n);
              break;
            case 2:
              points.push_back(k);
              break;
            default:
              points.push_back(n * (n + 1) + k);
          }
      return points;
    }

    /// A 3D patch of @p n subdivisions whose points are given in rows.
    DataOutBase::Patch<2, 3>
    empty_patch(const unsigned int n, const unsigned int n_rows)
    {
      DataOutBase::Patch<2, 3> patch;
      patch.n_subdivisions       = n;
      patch.points_are_available = true;
      patch.reference_cell       = ReferenceCells::Quadrilateral;
      patch.data.reinit(n_rows + 3, (n + 1) * (n + 1));
      return patch;
    }

    /// Set the vertices of @p patch from its corner points.
    void
    set_vertices(DataOutBase::Patch<2, 3> &patch, const unsigned int n_rows)
    {
      const unsigned int n          = patch.n_subdivisions;
      const unsigned int corners[4] = {0, n, n * (n + 1), n * (n + 1) + n};
      for (unsigned int v = 0; v < 4; ++v)
        for (unsigned int d = 0; d < 3; ++d)
          patch.vertices[v][d] = patch.data(n_rows + d, corners[v]);
    }
  } // namespace

  RevolvedView::RevolvedView(
    const std::vector<DataOutBase::Patch<2, 2>> &patches,
    const std::vector<std::string>              &names,
    const RevolvedView::FieldRanges             &vector_ranges,
    const std::string                           &hoop_name,
    const Point<2>                              &centre,
    const double                                 radius,
    const double                                 angle,
    const unsigned int                           sectors)
  {
    require(angle > 0. && angle <= 2. * M_PI + 1e-12 && sectors > 0,
            "RevolvedView: the angle must lie in (0, 2 pi]");
    map_fields(names, vector_ranges, hoop_name);
    n_input_rows              = names.size();
    const unsigned int n_data = n_input_rows;
    const double       sector = angle / sectors;
    for (const auto &source : patches)
      {
        const unsigned int n = source.n_subdivisions;
        // The meridian planes at both ends of the sweep.
        for (const double phi : {0., angle})
          {
            auto patch = empty_patch(n, n_output_rows);
            for (unsigned int j = 0; j < (n + 1) * (n + 1); ++j)
              fill_point(source, j, phi, patch, j);
            set_vertices(patch, n_output_rows);
            revolved.push_back(std::move(patch));
          }
        // The curved edges, swept sector by sector.
        for (unsigned int e = 0; e < 4; ++e)
          {
            const auto points  = edge_points(e, n);
            bool       on_edge = true;
            for (const unsigned int j : {points.front(), points.back()})
              on_edge =
                on_edge &&
                std::abs(patch_point(source, j, n_data).distance(centre) -
                         radius) < 1e-6 * radius;
            const bool on_axis =
              std::abs(patch_point(source, points.front(), n_data)[1]) <
                1e-9 * radius &&
              std::abs(patch_point(source, points.back(), n_data)[1]) <
                1e-9 * radius;
            if (!on_edge || on_axis)
              continue;
            for (unsigned int s = 0; s < sectors; ++s)
              {
                auto patch = empty_patch(n, n_output_rows);
                for (unsigned int k = 0; k <= n; ++k)
                  for (unsigned int i = 0; i <= n; ++i)
                    fill_point(source,
                               points[i],
                               (s + double(k) / n) * sector,
                               patch,
                               k * (n + 1) + i);
                set_vertices(patch, n_output_rows);
                revolved.push_back(std::move(patch));
              }
          }
      }
    for (unsigned int p = 0; p < revolved.size(); ++p)
      revolved[p].patch_index = p;
  }

  void
  RevolvedView::map_fields(const std::vector<std::string>  &names,
                           const RevolvedView::FieldRanges &vector_ranges,
                           const std::string               &hoop_name)
  {
    const auto hoop = std::find(names.begin(), names.end(), hoop_name);
    require(hoop != names.end(),
            "RevolvedView: no field '" + hoop_name + "' to revolve with");
    hoop_row = hoop - names.begin();
    for (unsigned int row = 0; row < names.size();)
      {
        Field        field{Field::scalar, row, n_output_rows};
        unsigned int width = 1, output_width = 1;
        for (const auto &[first, last, name, kind] : vector_ranges)
          if (first == row)
            {
              width = last - first + 1;
              require(
                (kind ==
                   DataComponentInterpretation::component_is_part_of_vector &&
                 width == 2) ||
                  (kind ==
                     DataComponentInterpretation::component_is_part_of_tensor &&
                   width == 4),
                "RevolvedView: field '" + name +
                  "' is neither a 2-vector nor a 2x2 tensor");
              field.kind   = width == 2 ? Field::vector : Field::tensor;
              output_width = width == 2 ? 3 : 9;
            }
        fields.push_back(field);
        for (unsigned int k = 0; k < output_width; ++k)
          output_names.push_back(names[row]);
        n_output_rows += output_width;
        row += width;
      }
  }

  void
  RevolvedView::fill_point(const DataOutBase::Patch<2, 2> &source,
                           const unsigned int              in,
                           const double                    phi,
                           DataOutBase::Patch<2, 3>       &patch,
                           const unsigned int              out) const
  {
    const double   c = std::cos(phi), s = std::sin(phi);
    const Point<2> x    = patch_point(source, in, n_input_rows);
    auto          &data = patch.data;
    for (const auto &field : fields)
      {
        const auto input = [&](const unsigned int k) {
          return double(source.data(field.input + k, in));
        };
        const unsigned int o = field.output;
        switch (field.kind)
          {
            case Field::scalar:
              data(o, out) = input(0);
              break;
            case Field::vector:
              data(o, out)     = input(0);
              data(o + 1, out) = input(1) * c;
              data(o + 2, out) = input(1) * s;
              break;
            case Field::tensor:
              {
                // (e_x, e_r, e_theta) with e_r = (0, c, s), e_theta =
                // (0, -s, c); unrolled 2x2 input (xx, xy, yx, yy).
                const double xx = input(0), xr = input(1), rr = input(3);
                const double tt      = source.data(hoop_row, in);
                const double t[3][3] = {
                  {xx, xr * c, xr * s},
                  {xr * c, rr * c * c + tt * s * s, (rr - tt) * c * s},
                  {xr * s, (rr - tt) * c * s, rr * s * s + tt * c * c}};
                for (unsigned int i = 0; i < 3; ++i)
                  for (unsigned int j = 0; j < 3; ++j)
                    data(o + 3 * i + j, out) = t[i][j];
              }
          }
      }
    data(n_output_rows, out)     = x[0];
    data(n_output_rows + 1, out) = x[1] * c;
    data(n_output_rows + 2, out) = x[1] * s;
  }

  const std::vector<DataOutBase::Patch<2, 3>> &
  RevolvedView::get_patches() const
  {
    return revolved;
  }

  std::vector<std::string>
  RevolvedView::get_dataset_names() const
  {
    return output_names;
  }

  RevolvedView::FieldRanges
  RevolvedView::get_nonscalar_data_ranges() const
  {
    FieldRanges ranges;
    for (const auto &field : fields)
      if (field.kind == Field::vector)
        ranges.emplace_back(
          field.output,
          field.output + 2,
          output_names[field.output],
          DataComponentInterpretation::component_is_part_of_vector);
      else if (field.kind == Field::tensor)
        ranges.emplace_back(
          field.output,
          field.output + 8,
          output_names[field.output],
          DataComponentInterpretation::component_is_part_of_tensor);
    return ranges;
  }
} // namespace DiskImpact
