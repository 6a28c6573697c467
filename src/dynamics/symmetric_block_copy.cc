#include "dynamics/symmetric_block_copy.h"

#include "base/petsc_check.h"

#include <deal.II/base/exceptions.h>

#include <algorithm>

namespace DiskImpact
{
  SymmetricBlockCopy::SymmetricBlockCopy(Mat sequential, PetscInt block_size)
      : block_size(block_size)
  {
    const auto graph    = block_graph(sequential);
    const auto position = minimum_degree_order(graph);
    const auto n_blocks = static_cast<PetscInt>(graph.size());

    new_row.resize(n_blocks * block_size);
    for (PetscInt i = 0; i < n_blocks * block_size; ++i)
      new_row[i] = position[i / block_size] * block_size + i % block_size;

    // Preallocation: the blocks at or right of the diagonal, per new row.
    std::vector<PetscInt> upper(n_blocks, 0);
    for (PetscInt b = 0; b < n_blocks; ++b)
      for (const PetscInt c : graph[b])
        if (position[c] >= position[b])
          ++upper[position[b]];
    check_petsc(MatCreateSeqSBAIJ(PETSC_COMM_SELF,
                                  block_size,
                                  n_blocks * block_size,
                                  n_blocks * block_size,
                                  0,
                                  upper.data(),
                                  &copy),
                "MatCreateSeqSBAIJ");
    check_petsc(MatSetOption(copy, MAT_IGNORE_LOWER_TRIANGULAR, PETSC_TRUE),
                "MatSetOption");
  }

  void
  SymmetricBlockCopy::copy_values(
    const std::vector<std::pair<PetscScalar, Mat>> &terms)
  {
    // Values before: zero them. None (the first call): the terms make the
    // pattern, which later values must fit.
    PetscBool filled;
    check_petsc(MatAssembled(copy, &filled), "MatAssembled");
    if (filled)
      check_petsc(MatZeroEntries(copy), "MatZeroEntries");
    for (const auto &[coefficient, sequential] : terms)
      add_values(coefficient, sequential);
    check_petsc(MatAssemblyBegin(copy, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    check_petsc(MatAssemblyEnd(copy, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    if (!filled)
      check_petsc(MatSetOption(copy, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE),
                  "MatSetOption");
  }

  void
  SymmetricBlockCopy::add_values(const PetscScalar coefficient, Mat sequential)
  {
    PetscInt n_rows;
    check_petsc(MatGetSize(sequential, &n_rows, nullptr), "MatGetSize");
    AssertThrow(n_rows == static_cast<PetscInt>(new_row.size()),
                dealii::ExcDimensionMismatch(n_rows, new_row.size()));
    std::vector<PetscInt>    columns;
    std::vector<PetscScalar> scaled;
    for (PetscInt i = 0; i < n_rows; ++i)
      {
        PetscInt           n_entries;
        const PetscInt    *old_columns;
        const PetscScalar *values;
        check_petsc(MatGetRow(sequential, i, &n_entries, &old_columns, &values),
                    "MatGetRow");
        columns.resize(n_entries);
        scaled.resize(n_entries);
        for (PetscInt k = 0; k < n_entries; ++k)
          {
            columns[k] = new_row[old_columns[k]];
            scaled[k]  = coefficient * values[k];
          }
        check_petsc(MatSetValues(copy,
                                 1,
                                 &new_row[i],
                                 n_entries,
                                 columns.data(),
                                 scaled.data(),
                                 ADD_VALUES),
                    "MatSetValues");
        check_petsc(
          MatRestoreRow(sequential, i, &n_entries, &old_columns, &values),
          "MatRestoreRow");
      }
  }

  SymmetricBlockCopy::~SymmetricBlockCopy()
  {
    if (copy != nullptr)
      MatDestroy(&copy);
  }

  Mat
  SymmetricBlockCopy::matrix() const
  {
    return copy;
  }

  std::vector<std::vector<PetscInt>>
  SymmetricBlockCopy::block_graph(Mat sequential) const
  {
    PetscInt n_rows;
    check_petsc(MatGetSize(sequential, &n_rows, nullptr), "MatGetSize");
    std::vector<std::vector<PetscInt>> graph(n_rows / block_size);
    for (PetscInt i = 0; i < n_rows; ++i)
      {
        PetscInt        n_entries;
        const PetscInt *columns;
        check_petsc(MatGetRow(sequential, i, &n_entries, &columns, nullptr),
                    "MatGetRow");
        auto &blocks = graph[i / block_size];
        for (PetscInt k = 0; k < n_entries; ++k)
          blocks.push_back(columns[k] / block_size);
        check_petsc(MatRestoreRow(sequential, i, &n_entries, &columns, nullptr),
                    "MatRestoreRow");
      }
    for (PetscInt b = 0; b < static_cast<PetscInt>(graph.size()); ++b)
      {
        graph[b].push_back(b);
        std::sort(graph[b].begin(), graph[b].end());
        graph[b].erase(std::unique(graph[b].begin(), graph[b].end()),
                       graph[b].end());
      }
    return graph;
  }

  std::vector<PetscInt>
  SymmetricBlockCopy::minimum_degree_order(
    const std::vector<std::vector<PetscInt>> &graph)
  {
    // The block graph as a pattern matrix, ordered by PETSc's AMD
    // (SuiteSparse).
    const auto            n_blocks = static_cast<PetscInt>(graph.size());
    std::vector<PetscInt> row_start{0}, columns;
    for (const auto &row : graph)
      {
        columns.insert(columns.end(), row.begin(), row.end());
        row_start.push_back(columns.size());
      }
    std::vector<PetscScalar> ones(columns.size(), 1.);
    Mat                      pattern;
    check_petsc(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF,
                                          n_blocks,
                                          n_blocks,
                                          row_start.data(),
                                          columns.data(),
                                          ones.data(),
                                          &pattern),
                "MatCreateSeqAIJWithArrays");
    IS row_order, column_order;
    check_petsc(
      MatGetOrdering(pattern, MATORDERINGAMD, &row_order, &column_order),
      "MatGetOrdering");
    const PetscInt *old_block;
    check_petsc(ISGetIndices(row_order, &old_block), "ISGetIndices");
    std::vector<PetscInt> position(n_blocks);
    for (PetscInt k = 0; k < n_blocks; ++k)
      position[old_block[k]] = k;
    check_petsc(ISRestoreIndices(row_order, &old_block), "ISRestoreIndices");
    ISDestroy(&row_order);
    ISDestroy(&column_order);
    MatDestroy(&pattern);
    return position;
  }

  void
  SymmetricBlockCopy::to_copy_order(Vec in, Vec out) const
  {
    const PetscScalar *from;
    PetscScalar       *to;
    check_petsc(VecGetArrayRead(in, &from), "VecGetArrayRead");
    check_petsc(VecGetArray(out, &to), "VecGetArray");
    for (std::size_t i = 0; i < new_row.size(); ++i)
      to[new_row[i]] = from[i];
    check_petsc(VecRestoreArray(out, &to), "VecRestoreArray");
    check_petsc(VecRestoreArrayRead(in, &from), "VecRestoreArrayRead");
  }

  void
  SymmetricBlockCopy::from_copy_order(Vec in, Vec out) const
  {
    const PetscScalar *from;
    PetscScalar       *to;
    check_petsc(VecGetArrayRead(in, &from), "VecGetArrayRead");
    check_petsc(VecGetArray(out, &to), "VecGetArray");
    for (std::size_t i = 0; i < new_row.size(); ++i)
      to[i] = from[new_row[i]];
    check_petsc(VecRestoreArray(out, &to), "VecRestoreArray");
    check_petsc(VecRestoreArrayRead(in, &from), "VecRestoreArrayRead");
  }
} // namespace DiskImpact
