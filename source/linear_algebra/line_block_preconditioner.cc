#include <algorithm>

#include <ssc/linear_algebra/line_block_preconditioner.h>

// LAPACK's banded Cholesky factorisation and solve (deal.II's
// lapack_templates.h has no banded routines).
extern "C"
{
  void
  dpbtrf_(const char *uplo,
          const int  *n,
          const int  *kd,
          double     *ab,
          const int  *ldab,
          int        *info);
  void
  dpbtrs_(const char   *uplo,
          const int    *n,
          const int    *kd,
          const int    *nrhs,
          const double *ab,
          const int    *ldab,
          double       *b,
          const int    *ldb,
          int          *info);
}

namespace ssc
{
  template <typename RowVisitor>
  bool
  LineBlockPreconditioner::factorize(const types::global_dof_index n_rows,
                                     const DoFLines               &dof_lines,
                                     const RowVisitor &for_each_in_row)
  {
    AssertThrow(dof_lines.line.size() == n_rows &&
                  dof_lines.position.size() == n_rows,
                ExcMessage("LineBlockPreconditioner: one line and one "
                           "position per row are needed (" +
                           std::to_string(dof_lines.line.size()) + " for " +
                           std::to_string(n_rows) + " rows)."));
    size = n_rows;
    const unsigned int n_lines =
      size == 0 ?
        0 :
        *std::max_element(dof_lines.line.begin(), dof_lines.line.end()) + 1;
    lines.assign(n_lines, Line());
    for (types::global_dof_index i = 0; i < size; ++i)
      lines[dof_lines.line[i]].dofs.push_back(i);

    // each line's DoFs by position (then index: the components of a node
    // stay together), and every DoF's place in its line
    std::vector<int> place(size);
    for (Line &line : lines)
      {
        std::stable_sort(line.dofs.begin(),
                         line.dofs.end(),
                         [&](const auto a, const auto b) {
                           return dof_lines.position[a] < dof_lines.position[b];
                         });
        for (unsigned int k = 0; k < line.dofs.size(); ++k)
          place[line.dofs[k]] = k;
      }
    for (types::global_dof_index row = 0; row < size; ++row)
      for_each_in_row(row, [&](const auto column, const double) {
        if (dof_lines.line[column] == dof_lines.line[row])
          {
            Line &line = lines[dof_lines.line[row]];
            line.bandwidth =
              std::max(line.bandwidth, std::abs(place[row] - place[column]));
          }
      });

    std::size_t longest = 0;
    for (Line &line : lines)
      {
        const int n = line.dofs.size(), rows = line.bandwidth + 1;
        line.band.assign(static_cast<std::size_t>(rows) * n, 0.);
        // lower band: entry (i, j), j <= i, at row i - j of column j
        for (int i = 0; i < n; ++i)
          for_each_in_row(
            line.dofs[i], [&](const auto column, const double value) {
              if (dof_lines.line[column] == dof_lines.line[line.dofs[i]] &&
                  place[column] <= i)
                {
                  const int j = place[column];
                  line.band[static_cast<std::size_t>(j) * rows + (i - j)] =
                    value;
                }
            });
        int info = 0;
        dpbtrf_("L", &n, &line.bandwidth, line.band.data(), &rows, &info);
        if (info != 0)
          {
            lines.clear();
            size = 0;
            return false;
          }
        longest = std::max<std::size_t>(longest, n);
      }
    buffer.resize(longest);
    return true;
  }


  bool
  LineBlockPreconditioner::initialize(const SparseMatrix<double> &matrix,
                                      const DoFLines             &dof_lines)
  {
    return factorize(matrix.m(), dof_lines, [&](const auto row, auto &&visit) {
      for (auto entry = matrix.begin(row); entry != matrix.end(row); ++entry)
        visit(entry->column(), entry->value());
    });
  }


  bool
  LineBlockPreconditioner::initialize(const Epetra_CrsMatrix &matrix,
                                      const DoFLines         &dof_lines,
                                      const Epetra_CrsMatrix *more_rows)
  {
    // row r < n_owned is the matrix's, row n_owned + k the k-th of
    // more_rows; a column that is none of them couples to a DoF that is on
    // no line here
    const int         n_owned       = matrix.NumMyRows();
    const Epetra_Map &rows          = matrix.RowMap();
    const auto local_row_of_columns = [&](const Epetra_CrsMatrix &source) {
      const Epetra_Map &columns = source.ColMap();
      std::vector<int>  local(columns.NumMyElements());
      for (int k = 0; k < columns.NumMyElements(); ++k)
        {
          local[k] = rows.LID(columns.GID64(k));
          if (local[k] < 0 && more_rows != nullptr)
            {
              const int more = more_rows->RowMap().LID(columns.GID64(k));
              local[k]       = more < 0 ? -1 : n_owned + more;
            }
        }
      return local;
    };
    const std::vector<int> owned_columns = local_row_of_columns(matrix);
    const std::vector<int> more_columns  = more_rows == nullptr ?
                                             std::vector<int>() :
                                             local_row_of_columns(*more_rows);
    const int              n_rows =
      n_owned + (more_rows == nullptr ? 0 : more_rows->NumMyRows());
    return factorize(n_rows, dof_lines, [&](const auto row, auto &&visit) {
      const bool              owned  = static_cast<int>(row) < n_owned;
      const Epetra_CrsMatrix &source = owned ? matrix : *more_rows;
      const std::vector<int> &local  = owned ? owned_columns : more_columns;
      int                     length;
      double                 *values;
      int                    *columns;
      source.ExtractMyRowView(owned ? row : row - n_owned,
                              length,
                              values,
                              columns);
      for (int k = 0; k < length; ++k)
        if (local[columns[k]] >= 0)
          visit(static_cast<types::global_dof_index>(local[columns[k]]),
                values[k]);
    });
  }


  void
  LineBlockPreconditioner::vmult(double *dst, const double *src) const
  {
    const int one = 1;
    for (const Line &line : lines)
      {
        const int n = line.dofs.size(), rows = line.bandwidth + 1;
        if (n == 0) // a line whose DoFs are all solved elsewhere
          continue;
        for (int k = 0; k < n; ++k)
          buffer[k] = src[line.dofs[k]];
        int info = 0;
        dpbtrs_("L",
                &n,
                &line.bandwidth,
                &one,
                line.band.data(),
                &rows,
                buffer.data(),
                &n,
                &info);
        for (int k = 0; k < n; ++k)
          dst[line.dofs[k]] = buffer[k];
      }
  }


  void
  LineBlockPreconditioner::vmult(Vector<double>       &dst,
                                 const Vector<double> &src) const
  {
    AssertDimension(src.size(), size);
    vmult(dst.begin(), src.begin());
  }


  void
  LineBlockPreconditioner::vmult(TrilinosWrappers::MPI::Vector       &dst,
                                 const TrilinosWrappers::MPI::Vector &src) const
  {
    AssertDimension(src.locally_owned_size(), size);
    vmult(dst.begin(), src.begin());
  }


  void
  LineBlockPreconditioner::Tvmult(Vector<double>       &dst,
                                  const Vector<double> &src) const
  {
    vmult(dst, src);
  }


  void
  LineBlockPreconditioner::Tvmult(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    vmult(dst, src);
  }


  types::global_dof_index
  LineBlockPreconditioner::m() const
  {
    return size;
  }


  types::global_dof_index
  LineBlockPreconditioner::n() const
  {
    return size;
  }


  unsigned int
  LineBlockPreconditioner::n_lines() const
  {
    return lines.size();
  }


  unsigned int
  LineBlockPreconditioner::max_bandwidth() const
  {
    int widest = 0;
    for (const Line &line : lines)
      widest = std::max(widest, line.bandwidth);
    return widest;
  }
} // namespace ssc
