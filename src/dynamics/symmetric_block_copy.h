#pragma once

#include <petscmat.h>

#include <utility>
#include <vector>

namespace DiskImpact
{
  /**
   * A sequential symmetric matrix copied into PETSc's symmetric block
   * format (SeqSBAIJ): each run of @p block_size consecutive rows (the
   * components of one support point, after DoFRenumbering::
   * support_point_wise) is one block row, and the block rows are reordered
   * by approximate minimum degree (AMD) on the graph of the blocks. PETSc's
   * Cholesky factorizes this copy in its natural order with its block
   * kernels, several times faster than the scalar matrix with nested
   * dissection; the solves are faster with cubic and quartic elements,
   * slower with quadratic ones (docs/theory/impact-method.md, "The condensed
   * contact solve"). Any grouping of the rows gives the same solution; the
   * grouping by support point gives the densest blocks.
   */
  class SymmetricBlockCopy
  {
  public:
    /// The copy's order and allocation for the pattern of @p sequential;
    /// copy_values() gives it its values.
    SymmetricBlockCopy(Mat sequential, PetscInt block_size);
    ~SymmetricBlockCopy();
    SymmetricBlockCopy(const SymmetricBlockCopy &) = delete;
    SymmetricBlockCopy &
    operator=(const SymmetricBlockCopy &) = delete;

    /// The values of sum_i c_i A_i for the @p terms (c_i, A_i), sequential
    /// matrices whose patterns lie within the first matrix's, into the
    /// copy: the order and the allocation stay. Each entry is
    /// ((c_1 a_1 + c_2 a_2) + ...), as PETSc's MatScale and MatAXPY sum.
    void
    copy_values(const std::vector<std::pair<PetscScalar, Mat>> &terms);

    /// The copy (upper block triangle), in the new order.
    Mat
    matrix() const;

    /// out = in in the copy's order.
    void
    to_copy_order(Vec in, Vec out) const;

    /// out = in in the original order.
    void
    from_copy_order(Vec in, Vec out) const;

  private:
    /// Add @p coefficient times the values of @p sequential to the copy.
    void
    add_values(PetscScalar coefficient, Mat sequential);

    /// The blocks each block row couples with (the diagonal included).
    std::vector<std::vector<PetscInt>>
    block_graph(Mat sequential) const;

    /// position[b]: block b's position in the AMD order.
    static std::vector<PetscInt>
    minimum_degree_order(const std::vector<std::vector<PetscInt>> &graph);

    PetscInt              block_size;
    std::vector<PetscInt> new_row;
    Mat                   copy = nullptr;
  };
} // namespace DiskImpact
