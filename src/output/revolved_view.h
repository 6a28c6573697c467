#pragma once

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/point.h>

#include <string>
#include <tuple>
#include <vector>

namespace DiskImpact
{
  /**
   * A ParaView-ready 3D view of a sphere's fields: the meridian's patches
   * (of a DataOut<2> on the half disk, x along the axis, y = r) revolved
   * about the axis y = 0 through a given angle. The view is a surface: the
   * sphere's curved edge swept into strips, and the two meridian planes at
   * the ends of the sweep, which show the interior.
   *
   * At the angle phi, with c = cos phi and s = sin phi, a point (x, r) goes to
   * (x, r c, r s). A vector field (u_x, u_r) goes to (u_x, u_r c, u_r s),
   * so ParaView's "Warp By Vector" works on the 3D view as on the meridian.
   * The stress tensor of the meridian plus the hoop stress (the scalar
   * field @p hoop_name) becomes the 3D tensor in the frame (e_x, e_r,
   * e_theta), rotated to Cartesian axes. Scalars are copied.
   */
  class RevolvedView : public dealii::DataOutInterface<2, 3>
  {
  public:
    /// The ranges of the vector and tensor fields, as DataOutInterface has
    /// them: (first, last, name, kind).
    using FieldRanges = std::vector<std::tuple<
      unsigned int,
      unsigned int,
      std::string,
      dealii::DataComponentInterpretation::DataComponentInterpretation>>;

    /**
     * Revolve the patches of the meridian's DataOut (@p patches, with its
     * @p names and @p vector_ranges) through @p angle (radians, at most
     * 2 pi) in @p sectors pieces. Edges whose ends lie at distance
     * @p radius from @p centre form the surface.
     */
    RevolvedView(const std::vector<dealii::DataOutBase::Patch<2, 2>> &patches,
                 const std::vector<std::string>                      &names,
                 const FieldRanges      &vector_ranges,
                 const std::string      &hoop_name,
                 const dealii::Point<2> &centre,
                 double                  radius,
                 double                  angle,
                 unsigned int            sectors);

    const std::vector<dealii::DataOutBase::Patch<2, 3>> &
    get_patches() const override;

    std::vector<std::string>
    get_dataset_names() const override;

    FieldRanges
    get_nonscalar_data_ranges() const override;

  private:
    /// How one input field maps to the output.
    struct Field
    {
      enum Kind
      {
        scalar,
        vector,
        tensor
      } kind;
      unsigned int input;  ///< first input row
      unsigned int output; ///< first output row
    };

    std::vector<Field>                            fields;
    unsigned int                                  hoop_row      = 0;
    unsigned int                                  n_input_rows  = 0;
    unsigned int                                  n_output_rows = 0;
    std::vector<std::string>                      output_names;
    std::vector<dealii::DataOutBase::Patch<2, 3>> revolved;

    void
    map_fields(const std::vector<std::string> &names,
               const FieldRanges              &vector_ranges,
               const std::string              &hoop_name);

    /// The output rows at point @p out of @p patch from input point @p in
    /// of @p source at the angle @p phi.
    void
    fill_point(const dealii::DataOutBase::Patch<2, 2> &source,
               unsigned int                            in,
               double                                  phi,
               dealii::DataOutBase::Patch<2, 3>       &patch,
               unsigned int                            out) const;
  };
} // namespace DiskImpact
