#pragma once

#include <petscmat.h>

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
   * slower with quadratic ones (docs/impact-convergence.md, "One rank's
   * solver"). Any grouping of the
   * rows gives the same solution; the grouping by support point gives the
   * densest blocks.
   */
  class SymmetricBlockCopy
  {
  public:
    SymmetricBlockCopy(Mat sequential, PetscInt block_size);
    ~SymmetricBlockCopy();
    SymmetricBlockCopy(const SymmetricBlockCopy &) = delete;
    SymmetricBlockCopy &
    operator=(const SymmetricBlockCopy &) = delete;

    /// The values of @p sequential, whose pattern is the first matrix's,
    /// into the copy: the order and the allocation stay.
    void
    copy_values(Mat sequential);

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
