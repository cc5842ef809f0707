// Does geometric multigrid keep CG's iteration count flat on the layered
// punch, where AMG does not (benchmarks/linear_solvers)? A prototype for
// issue 45, apart from ssc's solver: compressible elasticity on the
// layers of prm/punch.prm (skin, SAT, SM, DAT, deep; Young's moduli
// 0.02/0.001/0.06/0.001/0.015 MPa, contrast 1:60, or 1:1000 with SM at
// 1 MPa), a 60 mm square patch clamped at the bottom, a pressure of
// 0.01 MPa on the disk r < 5 mm of the skin surface. The coarse mesh has
// one cell per layer and n x n cells laterally; every level is a uniform
// refinement of it (a hierarchy ssc's meshes do not have yet).
//
// For each degree, refinement, nu and contrast: CG to a relative residual
// of 1e-8 preconditioned by
//  - gmg: a V-cycle, Chebyshev(degree 4) smoothing on the point-Jacobi
//    preconditioned level matrices (assembled on every level, the layers'
//    moduli inherited by the children), UMFPACK on the coarse level;
//  - amg: Trilinos ML smoothed aggregation with the three translation
//    modes (ssc's cg option, without the rotations).
// Prints one CSV line per case.
//
//   multigrid_layered [max refinements Q1] [max refinements Q2]
//                     [lateral coarse cells n] [quick: nu 0.3, 1:60 only]
//                     [Chebyshev degree] [equal: five 3.6 mm layers]

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <deal.II/numerics/vector_tools.h>

#include <deal.II/multigrid/mg_coarse.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/mg_tools.h>
#include <deal.II/multigrid/mg_transfer.h>
#include <deal.II/multigrid/multigrid.h>

#include <iostream>
#include <string>

using namespace dealii;

namespace
{
  constexpr unsigned int dim = 3;

  struct Case
  {
    unsigned int degree;
    unsigned int refinements;
    double       nu;
    double       contrast; // 60 or 1000
    unsigned int lateral_cells;
    /// Chebyshev degree of the multigrid smoother.
    unsigned int smoother_degree;
    /// Five layers of equal thickness (3.6 mm) instead of punch.prm's.
    bool equal_layers;
  };

  /// Layer thicknesses (mm, from the top) of prm/punch.prm, or five
  /// equal ones of the same total (cells without a thin layer).
  std::vector<double>
  layer_thicknesses(const bool equal_layers)
  {
    if (equal_layers)
      return std::vector<double>(5, 3.6);
    return {1.5, 3, 0.5, 3, 10};
  }

  /// The layers' Young's moduli (MPa); SM stiffened for 1:1000.
  std::vector<double>
  moduli(const double contrast)
  {
    return {0.02, 0.001, contrast > 100 ? 1.0 : 0.06, 0.001, 0.015};
  }

  /// The exact inverse of the coarse level's matrix.
  class DirectCoarse : public MGCoarseGridBase<Vector<double>>
  {
  public:
    void
    initialize(const SparseMatrix<double> &matrix)
    {
      solver.initialize(matrix);
    }

    void
    operator()(const unsigned int,
               Vector<double>       &dst,
               const Vector<double> &src) const override
    {
      solver.vmult(dst, src);
    }

  private:
    SparseDirectUMFPACK solver;
  };


  class LayeredPunch
  {
  public:
    explicit LayeredPunch(const Case &c);

    void
    run();

  private:
    template <typename Iterator>
    void
    cell_system(const Iterator     &cell,
                FullMatrix<double> &matrix,
                Vector<double>     &rhs) const;

    void
    assemble_active();

    void
    assemble_levels();

    void
    solve_gmg();

    void
    solve_amg();

    /// CG on the system with @p preconditioner, at most
    /// @p max_iterations (the count reported if it does not converge), and
    /// one CSV line.
    template <typename MatrixType, typename PreconditionerType>
    void
    solve_and_report(const std::string        &method,
                     const MatrixType         &system_matrix,
                     const PreconditionerType &preconditioner,
                     unsigned int              max_iterations,
                     double                    setup) const;

    const Case          c;
    std::vector<double> thicknesses, lambda, mu;

    Triangulation<dim>        tria;
    FESystem<dim>             fe;
    DoFHandler<dim>           dof_handler;
    AffineConstraints<double> constraints;
    SparsityPattern           sparsity;
    SparseMatrix<double>      matrix;
    Vector<double>            rhs;

    MGConstrainedDoFs                   mg_constrained_dofs;
    MGLevelObject<SparsityPattern>      mg_sparsity;
    MGLevelObject<SparseMatrix<double>> mg_matrices;
  };


  LayeredPunch::LayeredPunch(const Case &c)
    : c(c)
    , thicknesses(layer_thicknesses(c.equal_layers))
    , tria(Triangulation<dim>::limit_level_difference_at_vertices)
    , fe(FE_Q<dim>(c.degree), dim)
    , dof_handler(tria)
  {
    for (const double E : moduli(c.contrast))
      {
        lambda.push_back(E * c.nu / ((1 + c.nu) * (1 - 2 * c.nu)));
        mu.push_back(E / (2 * (1 + c.nu)));
      }
    double depth = 0;
    for (const double t : thicknesses)
      depth += t;
    const std::vector<double> lateral(c.lateral_cells, 60. / c.lateral_cells);
    const std::vector<std::vector<double>> steps = {
      lateral,
      lateral,
      std::vector<double>(thicknesses.rbegin(), thicknesses.rend())};
    GridGenerator::subdivided_hyper_rectangle(
      tria, steps, Point<dim>(-30, -30, -depth), Point<dim>(30, 30, 0), true);
    for (const auto &cell : tria.active_cell_iterators())
      {
        // the layer of the cell's centre, counted from the top
        double       top = 0;
        unsigned int l   = 0;
        while (l + 1 < thicknesses.size() &&
               -cell->center()[2] > top + thicknesses[l])
          top += thicknesses[l++];
        cell->set_material_id(l);
      }
    tria.refine_global(c.refinements);
  }


  template <typename Iterator>
  void
  LayeredPunch::cell_system(const Iterator     &cell,
                            FullMatrix<double> &cell_matrix,
                            Vector<double>     &cell_rhs) const
  {
    const QGauss<dim>     quadrature(c.degree + 1);
    const QGauss<dim - 1> face_quadrature(c.degree + 1);
    FEValues<dim>         fe_values(fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    FEFaceValues<dim>     face_values(fe,
                                  face_quadrature,
                                  update_values | update_quadrature_points |
                                    update_JxW_values);
    const unsigned int    n = fe.n_dofs_per_cell();
    cell_matrix.reinit(n, n);
    cell_rhs.reinit(n);
    fe_values.reinit(cell);
    const unsigned int l = cell->material_id();
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int   ci = fe.system_to_component_index(i).first;
          const Tensor<1, dim> gi = fe_values.shape_grad(i, q);
          for (unsigned int j = 0; j < n; ++j)
            {
              const unsigned int   cj = fe.system_to_component_index(j).first;
              const Tensor<1, dim> gj = fe_values.shape_grad(j, q);
              double a = lambda[l] * gi[ci] * gj[cj] + mu[l] * gi[cj] * gj[ci];
              if (ci == cj)
                a += mu[l] * (gi * gj);
              cell_matrix(i, j) += a * fe_values.JxW(q);
            }
        }
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 5)
        {
          face_values.reinit(cell, f);
          for (unsigned int q = 0; q < face_quadrature.size(); ++q)
            {
              const Point<dim> &p = face_values.quadrature_point(q);
              if (p[0] * p[0] + p[1] * p[1] > 25)
                continue;
              for (unsigned int i = 0; i < n; ++i)
                if (fe.system_to_component_index(i).first == 2)
                  cell_rhs(i) -=
                    0.01 * face_values.shape_value(i, q) * face_values.JxW(q);
            }
        }
  }


  void
  LayeredPunch::assemble_active()
  {
    dof_handler.distribute_dofs(fe);
    constraints.clear();
    VectorTools::interpolate_boundary_values(dof_handler,
                                             4,
                                             Functions::ZeroFunction<dim>(dim),
                                             constraints);
    constraints.close();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    sparsity.copy_from(dsp);
    matrix.reinit(sparsity);
    rhs.reinit(dof_handler.n_dofs());
    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell_system(cell, cell_matrix, cell_rhs);
        cell->get_dof_indices(indices);
        constraints.distribute_local_to_global(
          cell_matrix, cell_rhs, indices, matrix, rhs);
      }
  }


  void
  LayeredPunch::assemble_levels()
  {
    dof_handler.distribute_mg_dofs();
    mg_constrained_dofs.initialize(dof_handler);
    mg_constrained_dofs.make_zero_boundary_constraints(dof_handler, {4});
    const unsigned int n_levels = tria.n_levels();
    mg_sparsity.resize(0, n_levels - 1);
    mg_matrices.resize(0, n_levels - 1);
    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        DynamicSparsityPattern dsp(dof_handler.n_dofs(level));
        MGTools::make_sparsity_pattern(dof_handler, dsp, level);
        mg_sparsity[level].copy_from(dsp);
        mg_matrices[level].reinit(mg_sparsity[level]);
        AffineConstraints<double> boundary;
        boundary.add_lines(mg_constrained_dofs.get_boundary_indices(level));
        boundary.close();
        for (const auto &cell : dof_handler.cell_iterators_on_level(level))
          {
            cell_system(cell, cell_matrix, cell_rhs);
            cell->get_mg_dof_indices(indices);
            boundary.distribute_local_to_global(cell_matrix,
                                                indices,
                                                mg_matrices[level]);
          }
      }
  }


  template <typename MatrixType, typename PreconditionerType>
  void
  LayeredPunch::solve_and_report(const std::string        &method,
                                 const MatrixType         &system_matrix,
                                 const PreconditionerType &preconditioner,
                                 const unsigned int        max_iterations,
                                 const double              setup) const
  {
    Timer          timer;
    Vector<double> solution(dof_handler.n_dofs());
    SolverControl  control(max_iterations, 1e-8 * rhs.l2_norm(), false, false);
    SolverCG<Vector<double>> cg(control);
    unsigned int             iterations = max_iterations;
    try
      {
        cg.solve(system_matrix, solution, rhs, preconditioner);
        iterations = control.last_step();
      }
    catch (const SolverControl::NoConvergence &)
      {}
    std::cout << c.degree << ',' << c.refinements << ',' << c.nu << ','
              << c.contrast << ',' << c.lateral_cells << ','
              << c.smoother_degree << ',' << c.equal_layers << ','
              << dof_handler.n_dofs() << ',' << method << ',' << iterations
              << ',' << setup << ',' << timer.wall_time() << std::endl;
  }


  void
  LayeredPunch::solve_gmg()
  {
    Timer timer;
    assemble_levels();
    MGTransferPrebuilt<Vector<double>> transfer(mg_constrained_dofs);
    transfer.build(dof_handler);
    DirectCoarse coarse;
    coarse.initialize(mg_matrices[0]);
    using Smoother =
      PreconditionChebyshev<SparseMatrix<double>, Vector<double>>;
    mg::SmootherRelaxation<Smoother, Vector<double>> smoother;
    MGLevelObject<Smoother::AdditionalData>          smoother_data(0,
                                                          tria.n_levels() - 1);
    for (unsigned int level = 0; level < tria.n_levels(); ++level)
      {
        smoother_data[level].smoothing_range     = 15.;
        smoother_data[level].degree              = c.smoother_degree;
        smoother_data[level].eig_cg_n_iterations = 20;
        auto diagonal = std::make_shared<DiagonalMatrix<Vector<double>>>();
        diagonal->get_vector().reinit(dof_handler.n_dofs(level));
        for (unsigned int i = 0; i < dof_handler.n_dofs(level); ++i)
          diagonal->get_vector()(i) = 1. / mg_matrices[level].diag_element(i);
        smoother_data[level].preconditioner = diagonal;
      }
    smoother.initialize(mg_matrices, smoother_data);
    mg::Matrix<Vector<double>> level_matrix(mg_matrices);
    Multigrid<Vector<double>>  mg(
      level_matrix, coarse, transfer, smoother, smoother);
    PreconditionMG<dim, Vector<double>, MGTransferPrebuilt<Vector<double>>>
      preconditioner(dof_handler, mg, transfer);
    solve_and_report("gmg", matrix, preconditioner, 1000, timer.wall_time());
  }


  void
  LayeredPunch::solve_amg()
  {
    Timer                          timer;
    TrilinosWrappers::SparseMatrix trilinos_matrix;
    trilinos_matrix.reinit(matrix);
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = c.degree > 1;
    data.smoother_sweeps       = 2;
    data.aggregation_threshold = 0.02;
    std::vector<std::vector<bool>> modes;
    DoFTools::extract_constant_modes(dof_handler,
                                     ComponentMask(dim, true),
                                     modes);
    data.constant_modes = modes;
    TrilinosWrappers::PreconditionAMG amg;
    amg.initialize(trilinos_matrix, data);
    solve_and_report("amg", trilinos_matrix, amg, 2000, timer.wall_time());
  }


  void
  LayeredPunch::run()
  {
    assemble_active();
    solve_gmg();
    solve_amg();
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               max_q1  = argc > 1 ? std::stoi(argv[1]) : 3;
  const unsigned int               max_q2  = argc > 2 ? std::stoi(argv[2]) : 2;
  const unsigned int               lateral = argc > 3 ? std::stoi(argv[3]) : 6;
  const bool         quick = argc > 4 && std::string(argv[4]) == "quick";
  const unsigned int smoother_degree = argc > 5 ? std::stoi(argv[5]) : 4;
  const bool         equal_layers = argc > 6 && std::string(argv[6]) == "equal";
  std::cout << "degree,refinements,nu,contrast,lateral_cells,"
               "smoother_degree,equal_layers,dofs,method,iterations,"
               "setup_s,solve_s"
            << std::endl;
  for (const double contrast : {60., 1000.})
    for (const double nu : {0.3, 0.45, 0.49})
      for (const unsigned int degree : {1u, 2u})
        for (unsigned int r = 1; r <= (degree == 1 ? max_q1 : max_q2); ++r)
          if (!quick || (contrast == 60. && nu == 0.3))
            LayeredPunch(
              {degree, r, nu, contrast, lateral, smoother_degree, equal_layers})
              .run();
}
