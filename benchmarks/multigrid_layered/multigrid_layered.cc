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
//  - gmg-line: the same V-cycle with Chebyshev on the exact inverse of each
//    level's vertical line blocks (ssc::LineBlockPreconditioner);
//  - gmg-line-galerkin: gmg-line with Galerkin level matrices P^T A P
//    (ssc::make_galerkin_hierarchy) below the finest;
//  - amg: Trilinos ML smoothed aggregation with the three translation
//    modes (ssc's cg option, without the rotations); amg-line: the same
//    with ML's line Jacobi smoother;
//  - cholesky: ssc's CHOLMOD factor.
// Prints one CSV line per case (resident memory after the solve last).
//
//   multigrid_layered [q1=3] [q2=2] [n=6] [quick=0|1] [chebyshev=4]
//                     [equal=0|1] [smoothers=point,line] [amg=1]
//                     [amg-line=0] [cholesky=0] [galerkin=0]
//                     [nu=0.3,0.45,0.49]

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
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
#include <map>
#include <string>

#include <ssc/linear_algebra/cholesky_preconditioner.h>
#include <ssc/linear_algebra/line_block_preconditioner.h>
#include <ssc/multigrid/direct_coarse_solver.h>
#include <ssc/multigrid/galerkin_hierarchy.h>
#include <ssc/multigrid/vertical_lines.h>

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
    /// Which preconditioners to run.
    bool point_smoother;
    bool line_smoother;
    bool amg;
    bool amg_line;
    bool cholesky;
    bool galerkin;
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

  /// Resident memory of this process now (MB): the matrices and the
  /// preconditioner of the case being solved, when one method runs per
  /// process.
  double
  resident_memory_MB()
  {
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    return memory.VmRSS / 1024.;
  }


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

    /// A V-cycle with Chebyshev smoothing on the level preconditioners
    /// that @p make_preconditioner (level) returns.
    template <typename LevelPreconditioner, typename MakePreconditioner>
    void
    solve_gmg(const std::string        &method,
              const MakePreconditioner &make_preconditioner);

    /// gmg: point Jacobi inside Chebyshev.
    void
    solve_gmg_point();

    /// gmg-line: the vertical line blocks inside Chebyshev.
    void
    solve_gmg_line(const std::string &method = "gmg-line");

    /// Replaces the level matrices below the finest by Galerkin products
    /// P^T A P of the finer level's (what ssc needs: its septa, ligaments
    /// and contact are in the fine matrix only); Dirichlet DoFs are kept
    /// out of the transfer, their coarse rows are the identity.
    void
    make_galerkin_levels();

    /// ssc's sparse Cholesky factor (CHOLMOD): the scenes' fast path.
    void
    solve_cholesky();

    /// ML's smoothed aggregation, with its point smoother or with its
    /// line smoother on lines detected from the coordinates.
    void
    solve_amg(bool line_smoother);

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

    Triangulation<dim> tria;
    FESystem<dim>      fe;
    DoFHandler<dim>    dof_handler;
    /// Reused by every cell_system() call.
    mutable FEValues<dim>     fe_values;
    mutable FEFaceValues<dim> face_values;
    AffineConstraints<double> constraints;
    SparsityPattern           sparsity;
    SparseMatrix<double>      matrix;
    Vector<double>            rhs;

    MGConstrainedDoFs                   mg_constrained_dofs;
    MGLevelObject<SparsityPattern>      mg_sparsity;
    MGLevelObject<SparseMatrix<double>> mg_matrices;
    /// Wall time of the level matrices' assembly (s), part of every
    /// V-cycle's set-up.
    double level_setup = 0;
    /// The same for the finest level alone (the Galerkin hierarchy
    /// assembles only it).
    double finest_level_setup = 0;
  };


  LayeredPunch::LayeredPunch(const Case &c)
    : c(c)
    , thicknesses(layer_thicknesses(c.equal_layers))
    , tria(Triangulation<dim>::limit_level_difference_at_vertices)
    , fe(FE_Q<dim>(c.degree), dim)
    , dof_handler(tria)
    , fe_values(fe,
                QGauss<dim>(c.degree + 1),
                update_gradients | update_JxW_values)
    , face_values(fe,
                  QGauss<dim - 1>(c.degree + 1),
                  update_values | update_quadrature_points | update_JxW_values)
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
    const Quadrature<dim>     &quadrature      = fe_values.get_quadrature();
    const Quadrature<dim - 1> &face_quadrature = face_values.get_quadrature();
    const unsigned int         n               = fe.n_dofs_per_cell();
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
    Timer timer;
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
        Timer level_timer;
        for (const auto &cell : dof_handler.cell_iterators_on_level(level))
          {
            cell_system(cell, cell_matrix, cell_rhs);
            cell->get_mg_dof_indices(indices);
            boundary.distribute_local_to_global(cell_matrix,
                                                indices,
                                                mg_matrices[level]);
          }
        finest_level_setup = level_timer.wall_time();
      }
    level_setup = timer.wall_time();
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
              << ',' << setup << ',' << timer.wall_time() << ','
              << resident_memory_MB() << std::endl;
  }


  template <typename LevelPreconditioner, typename MakePreconditioner>
  void
  LayeredPunch::solve_gmg(const std::string        &method,
                          const MakePreconditioner &make_preconditioner)
  {
    Timer                              timer;
    MGTransferPrebuilt<Vector<double>> transfer(mg_constrained_dofs);
    transfer.build(dof_handler);
    ssc::DirectCoarseSolver coarse;
    coarse.initialize(mg_matrices[0]);
    using Smoother = PreconditionChebyshev<SparseMatrix<double>,
                                           Vector<double>,
                                           LevelPreconditioner>;
    mg::SmootherRelaxation<Smoother, Vector<double>> smoother;
    MGLevelObject<typename Smoother::AdditionalData> smoother_data(
      0, tria.n_levels() - 1);
    for (unsigned int level = 0; level < tria.n_levels(); ++level)
      {
        smoother_data[level].smoothing_range     = 15.;
        smoother_data[level].degree              = c.smoother_degree;
        smoother_data[level].eig_cg_n_iterations = 20;
        smoother_data[level].preconditioner      = make_preconditioner(level);
      }
    smoother.initialize(mg_matrices, smoother_data);
    mg::Matrix<Vector<double>> level_matrix(mg_matrices);
    Multigrid<Vector<double>>  mg(
      level_matrix, coarse, transfer, smoother, smoother);
    PreconditionMG<dim, Vector<double>, MGTransferPrebuilt<Vector<double>>>
      preconditioner(dof_handler, mg, transfer);
    solve_and_report(
      method, matrix, preconditioner, 1000, level_setup + timer.wall_time());
  }


  void
  LayeredPunch::solve_gmg_point()
  {
    solve_gmg<DiagonalMatrix<Vector<double>>>("gmg", [&](unsigned int level) {
      auto diagonal = std::make_shared<DiagonalMatrix<Vector<double>>>();
      diagonal->get_vector().reinit(dof_handler.n_dofs(level));
      for (unsigned int i = 0; i < dof_handler.n_dofs(level); ++i)
        diagonal->get_vector()(i) = 1. / mg_matrices[level].diag_element(i);
      return diagonal;
    });
  }


  void
  LayeredPunch::make_galerkin_levels()
  {
    Timer timer;
    ssc::make_galerkin_hierarchy(dof_handler,
                                 mg_constrained_dofs,
                                 mg_sparsity,
                                 mg_matrices);
    level_setup = finest_level_setup + timer.wall_time();
  }


  void
  LayeredPunch::solve_gmg_line(const std::string &method)
  {
    solve_gmg<ssc::LineBlockPreconditioner>(method, [&](unsigned int level) {
      auto lines = std::make_shared<ssc::LineBlockPreconditioner>();
      AssertThrow(
        lines->initialize(mg_matrices[level],
                          ssc::vertical_lines(dof_handler, level, 1e-6)),
        ExcMessage("a line block is not positive definite"));
      return lines;
    });
  }


  void
  LayeredPunch::solve_amg(const bool line_smoother)
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
    if (!line_smoother)
      {
        amg.initialize(trilinos_matrix, data);
        solve_and_report("amg", trilinos_matrix, amg, 2000, timer.wall_time());
        return;
      }
    // ML's own line smoother: the lines are detected from the nodes'
    // coordinates (neighbours much closer in z than laterally)
    Teuchos::ParameterList              ml_list;
    std::unique_ptr<Epetra_MultiVector> unused;
    data.set_parameters(ml_list, unused, trilinos_matrix);
    std::map<types::global_dof_index, Point<dim>> support;
    DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                         dof_handler,
                                         support);
    const unsigned int  n_nodes = dof_handler.n_dofs() / dim;
    std::vector<double> x(n_nodes), y(n_nodes), z(n_nodes);
    for (unsigned int node = 0; node < n_nodes; ++node)
      {
        const Point<dim> &p = support.at(dim * node);
        x[node] = p[0], y[node] = p[1], z[node] = p[2];
      }
    ml_list.set("PDE equations", 3);
    // the best settings found by hand: at a detection threshold of 0.1
    // the lines break in the thick layers, at damping 0.8 CG diverges
    ml_list.set("smoother: type", "line Jacobi");
    ml_list.set("smoother: line detection threshold", 0.5);
    ml_list.set("smoother: damping factor", 0.5);
    ml_list.set("x-coordinates", x.data());
    ml_list.set("y-coordinates", y.data());
    ml_list.set("z-coordinates", z.data());
    amg.initialize(trilinos_matrix, ml_list);
    solve_and_report("amg-line", trilinos_matrix, amg, 2000, timer.wall_time());
  }


  void
  LayeredPunch::solve_cholesky()
  {
    Timer                          timer;
    TrilinosWrappers::SparseMatrix trilinos_matrix;
    trilinos_matrix.reinit(matrix);
    ssc::CholeskyPreconditioner factor;
    factor.initialize(trilinos_matrix);
    solve_and_report(
      "cholesky", trilinos_matrix, factor, 100, timer.wall_time());
  }


  void
  LayeredPunch::run()
  {
    assemble_active();
    if (c.point_smoother || c.line_smoother)
      assemble_levels();
    if (c.point_smoother)
      solve_gmg_point();
    if (c.line_smoother)
      solve_gmg_line();
    if (c.amg)
      solve_amg(false);
    if (c.amg_line)
      solve_amg(true);
    if (c.cholesky)
      solve_cholesky();
    if (c.galerkin)
      {
        if (!(c.point_smoother || c.line_smoother))
          assemble_levels();
        make_galerkin_levels();
        solve_gmg_line("gmg-line-galerkin");
      }
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize   mpi(argc, argv, 1);
  std::map<std::string, std::string> options = {{"q1", "3"},
                                                {"q2", "2"},
                                                {"n", "6"},
                                                {"quick", "0"},
                                                {"chebyshev", "4"},
                                                {"equal", "0"},
                                                {"smoothers", "point"},
                                                {"amg", "1"},
                                                {"amg-line", "0"},
                                                {"cholesky", "0"},
                                                {"galerkin", "0"},
                                                {"nu", "0.3,0.45,0.49"}};
  for (int a = 1; a < argc; ++a)
    {
      const std::string argument(argv[a]);
      const auto        equals = argument.find('=');
      const std::string key    = argument.substr(0, equals);
      if (options.count(key) == 0)
        {
          std::cerr << "multigrid_layered: unknown option '" << argument
                    << "' (known: q1= q2= n= quick=0|1 chebyshev= equal=0|1 "
                       "smoothers=point|line|point,line amg=0|1 amg-line=0|1 "
                       "cholesky=0|1 galerkin=0|1 nu=0.3,0.45,...)"
                    << std::endl;
          return 1;
        }
      options[key] = argument.substr(equals + 1);
    }
  const unsigned int max_q1          = std::stoi(options["q1"]);
  const unsigned int max_q2          = std::stoi(options["q2"]);
  const unsigned int lateral         = std::stoi(options["n"]);
  const bool         quick           = options["quick"] == "1";
  const unsigned int smoother_degree = std::stoi(options["chebyshev"]);
  const bool         equal_layers    = options["equal"] == "1";
  const bool point    = options["smoothers"].find("point") != std::string::npos;
  const bool line     = options["smoothers"].find("line") != std::string::npos;
  const bool amg      = options["amg"] == "1";
  const bool amg_line = options["amg-line"] == "1";
  const bool cholesky = options["cholesky"] == "1";
  const bool galerkin = options["galerkin"] == "1";
  std::vector<double> nus;
  for (const std::string &nu : Utilities::split_string_list(options["nu"]))
    nus.push_back(std::stod(nu));
  std::cout << "degree,refinements,nu,contrast,lateral_cells,"
               "smoother_degree,equal_layers,dofs,method,iterations,"
               "setup_s,solve_s,memory_MB"
            << std::endl;
  for (const double contrast : {60., 1000.})
    for (const double nu : nus)
      for (const unsigned int degree : {1u, 2u})
        for (unsigned int r = 1; r <= (degree == 1 ? max_q1 : max_q2); ++r)
          if (!quick || (contrast == 60. && nu == 0.3))
            LayeredPunch({degree,
                          r,
                          nu,
                          contrast,
                          lateral,
                          smoother_degree,
                          equal_layers,
                          point,
                          line,
                          amg,
                          amg_line,
                          cholesky,
                          galerkin})
              .run();
}
