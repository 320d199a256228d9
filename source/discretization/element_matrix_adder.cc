#include <dyncontact/discretization/element_matrix_adder.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <limits>

namespace dyncontact
{
  ElementMatrixAdder::ElementMatrixAdder(TrilinosWrappers::SparseMatrix &matrix)
    : matrix(matrix)
    , epetra(const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix()))
    , direct(epetra.Filled() && epetra.IndicesAreLocal())
  {}



  void
  ElementMatrixAdder::add(const std::vector<types::global_dof_index> &dofs,
                          const FullMatrix<double> &element_matrix)
  {
    const unsigned int n = dofs.size();
    if (!direct)
      {
        matrix.add(dofs, element_matrix);
        return;
      }
    rows.resize(n);
    columns.resize(n);
    order.resize(n);
    positions.assign(n, std::numeric_limits<int>::max());
    for (unsigned int j = 0; j < n; ++j)
      {
        const auto gid =
          static_cast<TrilinosWrappers::types::int_type>(dofs[j]);
        rows[j]    = epetra.RowMap().LID(gid);
        columns[j] = epetra.ColMap().LID(gid);
        order[j]   = j;
      }
    std::sort(order.begin(),
              order.end(),
              [this](const unsigned int a, const unsigned int b) {
                return columns[a] < columns[b];
              });
    for (unsigned int i = 0; i < n; ++i)
      {
        if (rows[i] < 0)
          {
            // not owned here: Epetra keeps it for the owner until
            // compress()
            matrix.add(dofs[i], n, dofs.data(), &element_matrix(i, 0));
            continue;
          }
        int     length  = 0;
        double *values  = nullptr;
        int    *indices = nullptr;
        epetra.ExtractMyRowView(rows[i], length, values, indices);
        // Each entry is first looked for where the row before had it:
        // the rows of one node's components have the same columns. Else
        // a binary search from the entry before finds it (the
        // element's columns come in runs of neighbours in the row).
        const int *q = indices, *const end = indices + length;
        for (const unsigned int j : order)
          {
            const int p = positions[j];
            if (p < length && indices[p] == columns[j])
              {
                values[p] += element_matrix(i, j);
                q = indices + p + 1;
                continue;
              }
            if (q == end || *q != columns[j])
              q = std::lower_bound(q, end, columns[j]);
            if (q != end && *q == columns[j])
              {
                positions[j] = q - indices;
                values[q++ - indices] += element_matrix(i, j);
              }
            else
              matrix.add(dofs[i], dofs[j], element_matrix(i, j));
          }
      }
  }
} // namespace dyncontact
