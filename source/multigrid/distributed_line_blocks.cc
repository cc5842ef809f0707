#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_index_access.h>

#include <Epetra_MpiComm.h>

#include <map>
#include <utility>

#include <ssc/multigrid/distributed_line_blocks.h>
#include <ssc/multigrid/vertical_lines.h>

namespace ssc
{
  bool
  DistributedLineBlocks::initialize(const Epetra_CrsMatrix      &matrix,
                                    const DoFLines              &lines,
                                    const std::vector<Point<2>> &lateral,
                                    const double                 tolerance)
  {
    using int_type = TrilinosWrappers::types::int_type;
    const MPI_Comm communicator =
      dynamic_cast<const Epetra_MpiComm &>(matrix.Comm()).Comm();
    const unsigned int this_process =
      Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_lines = lateral.size();
    const int          n_owned = matrix.NumMyRows();
    AssertThrow(lines.line.size() == static_cast<std::size_t>(n_owned),
                ExcMessage("DistributedLineBlocks: one line per row of this "
                           "process is needed."));
    std::vector<unsigned int> count(n_lines, 0);
    for (const unsigned int line : lines.line)
      ++count[line];

    // every process's lines: (x, y, number of DoFs); the process holding
    // most of a line's DoFs solves it (the lowest such rank on a tie)
    std::vector<double> mine;
    for (unsigned int l = 0; l < n_lines; ++l)
      mine.insert(mine.end(), {lateral[l][0], lateral[l][1], 1. * count[l]});
    const auto all = Utilities::MPI::all_gather(communicator, mine);
    std::map<Point<2>, std::pair<unsigned int, double>, LateralLess> solver(
      LateralLess{tolerance});
    std::map<Point<2>, unsigned int, LateralLess> n_holders(
      LateralLess{tolerance});
    for (unsigned int rank = 0; rank < all.size(); ++rank)
      for (std::size_t k = 0; k + 2 < all[rank].size(); k += 3)
        {
          const Point<2> key(all[rank][k], all[rank][k + 1]);
          const auto [entry, inserted] =
            solver.emplace(key, std::make_pair(rank, all[rank][k + 2]));
          if (!inserted && all[rank][k + 2] > entry->second.second)
            entry->second = std::make_pair(rank, all[rank][k + 2]);
          ++n_holders[key];
        }
    cut_lines = 0;
    for (const auto &holders : n_holders)
      cut_lines += (holders.second > 1);
    given_away.clear();
    if (cut_lines == 0)
      {
        import.reset();
        extended_map.reset();
        const bool positive_definite = blocks.initialize(matrix, lines);
        return Utilities::MPI::min(positive_definite ? 1 : 0, communicator) ==
               1;
      }

    // the DoFs of lines that another process solves go there:
    // (solving process, x, y, global index, position)
    std::vector<double> given;
    for (int i = 0; i < n_owned; ++i)
      {
        const Point<2>    &key = lateral[lines.line[i]];
        const unsigned int by  = solver.at(key).first;
        if (by != this_process)
          {
            given.insert(given.end(),
                         {1. * by,
                          key[0],
                          key[1],
                          1. * matrix.RowMap().GID64(i),
                          lines.position[i]});
            given_away.push_back(i);
          }
      }
    const auto received = Utilities::MPI::all_gather(communicator, given);

    std::map<Point<2>, unsigned int, LateralLess> line_of(
      LateralLess{tolerance});
    for (unsigned int l = 0; l < n_lines; ++l)
      line_of.emplace(lateral[l], l);
    std::vector<int_type> indices(n_owned);
    for (int i = 0; i < n_owned; ++i)
      indices[i] = matrix.RowMap().GID64(i);
    DoFLines extended = lines;
    for (const auto &from : received)
      for (std::size_t k = 0; k + 4 < from.size(); k += 5)
        if (static_cast<unsigned int>(from[k]) == this_process)
          {
            indices.push_back(static_cast<int_type>(from[k + 3]));
            extended.line.push_back(
              line_of.at(Point<2>(from[k + 1], from[k + 2])));
            extended.position.push_back(from[k + 4]);
          }
    // each DoF given away is a line of its own here, whose value is
    // dropped (the solving process sends it)
    unsigned int next = n_lines;
    for (const int i : given_away)
      extended.line[i] = next++;

    extended_map =
      std::make_unique<Epetra_Map>(static_cast<int_type>(-1),
                                   static_cast<int>(indices.size()),
                                   indices.data(),
                                   static_cast<int_type>(0),
                                   matrix.Comm());
    import = std::make_unique<Epetra_Import>(*extended_map, matrix.RowMap());
    // the other processes' rows of the lines solved here
    const Epetra_Map more_map(static_cast<int_type>(-1),
                              static_cast<int>(indices.size() - n_owned),
                              indices.data() + n_owned,
                              static_cast<int_type>(0),
                              matrix.Comm());
    Epetra_CrsMatrix more_rows(Copy, more_map, 0);
    more_rows.Import(matrix, Epetra_Import(more_map, matrix.RowMap()), Insert);
    more_rows.FillComplete(matrix.DomainMap(), matrix.RangeMap());
    extended_src = std::make_unique<Epetra_Vector>(*extended_map);
    extended_dst = std::make_unique<Epetra_Vector>(*extended_map);
    const bool positive_definite =
      blocks.initialize(matrix, extended, &more_rows);
    return Utilities::MPI::min(positive_definite ? 1 : 0, communicator) == 1;
  }


  void
  DistributedLineBlocks::vmult(TrilinosWrappers::MPI::Vector       &dst,
                               const TrilinosWrappers::MPI::Vector &src) const
  {
    if (import == nullptr)
      {
        blocks.vmult(dst, src);
        return;
      }
    extended_src->Import(src.trilinos_vector(), *import, Insert);
    blocks.vmult(extended_dst->Values(), extended_src->Values());
    for (const int i : given_away)
      (*extended_dst)[i] = 0.;
    dst = 0.;
    dst.trilinos_vector().Export(*extended_dst, *import, Add);
  }


  void
  DistributedLineBlocks::Tvmult(TrilinosWrappers::MPI::Vector       &dst,
                                const TrilinosWrappers::MPI::Vector &src) const
  {
    vmult(dst, src);
  }


  unsigned int
  DistributedLineBlocks::n_cut_lines() const
  {
    return cut_lines;
  }
} // namespace ssc
