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
  bool
  LineBlockPreconditioner::initialize(const SparseMatrix<double> &matrix,
                                      const DoFLines             &dof_lines)
  {
    AssertThrow(dof_lines.line.size() == matrix.m() &&
                  dof_lines.position.size() == matrix.m(),
                ExcMessage("LineBlockPreconditioner: one line and one "
                           "position per row are needed (" +
                           std::to_string(dof_lines.line.size()) + " for " +
                           std::to_string(matrix.m()) + " rows)."));
    size = matrix.m();
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
      for (auto entry = matrix.begin(row); entry != matrix.end(row); ++entry)
        if (dof_lines.line[entry->column()] == dof_lines.line[row])
          {
            Line &line = lines[dof_lines.line[row]];
            line.bandwidth =
              std::max(line.bandwidth,
                       std::abs(place[row] - place[entry->column()]));
          }

    std::size_t longest = 0;
    for (Line &line : lines)
      {
        const int n = line.dofs.size(), rows = line.bandwidth + 1;
        line.band.assign(static_cast<std::size_t>(rows) * n, 0.);
        // lower band: entry (i, j), j <= i, at row i - j of column j
        for (int i = 0; i < n; ++i)
          for (auto entry = matrix.begin(line.dofs[i]);
               entry != matrix.end(line.dofs[i]);
               ++entry)
            if (dof_lines.line[entry->column()] ==
                  dof_lines.line[line.dofs[i]] &&
                place[entry->column()] <= i)
              {
                const int j = place[entry->column()];
                line.band[static_cast<std::size_t>(j) * rows + (i - j)] =
                  entry->value();
              }
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


  void
  LineBlockPreconditioner::vmult(Vector<double>       &dst,
                                 const Vector<double> &src) const
  {
    const int one = 1;
    for (const Line &line : lines)
      {
        const int n = line.dofs.size(), rows = line.bandwidth + 1;
        for (int k = 0; k < n; ++k)
          buffer[k] = src(line.dofs[k]);
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
          dst(line.dofs[k]) = buffer[k];
      }
  }


  void
  LineBlockPreconditioner::Tvmult(Vector<double>       &dst,
                                  const Vector<double> &src) const
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
