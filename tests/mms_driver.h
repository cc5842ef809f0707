#ifndef ssc_tests_mms_driver_h
#define ssc_tests_mms_driver_h

// Convergence study driver shared by the manufactured-solution tests: solves
// on the unit patch [-1/2, 1/2]^2 x [-1, 0] under global refinement with the
// exact solution as Dirichlet data on all six sides, and logs the L2 and H1
// errors with their observed rates.

#include <cmath>
#include <iomanip>
#include <iostream>

#include <ssc/mechanics/elastic_system.h>
#include <ssc/mesh/background_mesh.h>

#include "manufactured_solution.h"
#include "quiet_elasticity.h"
#include "tests.h"

namespace ssc_test
{
  inline void
  convergence_study(const std::string                 &label,
                    const ssc::LayerStack             &layers,
                    std::shared_ptr<const SmoothField> field,
                    const double                       nu,
                    const unsigned int                 degree,
                    const ssc::Formulation             formulation,
                    const unsigned int                 n_levels)
  {
    deallog << label << std::endl;
    const ExactDisplacement exact(field, layers);
    const BodyForce         force(field, nu);
    double                  last_l2 = 0, last_h1 = 0;
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        ssc::MeshParameters mesh_parameters;
        mesh_parameters.patch_length_x     = 1;
        mesh_parameters.patch_length_y     = 1;
        mesh_parameters.cell_size          = 0.5;
        mesh_parameters.core_half_width    = 1;
        mesh_parameters.global_refinements = level;
        ssc::BackgroundMesh mesh(layers, mesh_parameters, MPI_COMM_WORLD);
        mesh.build();

        ssc::ElasticityParameters parameters;
        parameters.degree                       = degree;
        parameters.formulation                  = formulation;
        parameters.linear_solver.tolerance      = 1e-12;
        parameters.linear_solver.max_iterations = 5000;
        QuietElasticity     quiet(mesh, layers, parameters);
        ssc::ElasticSystem &elasticity = quiet.elasticity;
        elasticity.field().distribute_dofs();
        std::vector<ssc::DirichletCondition> conditions;
        auto exact_ptr = std::make_shared<ExactDisplacement>(field, layers);
        for (types::boundary_id id = 0; id < 6; ++id)
          conditions.push_back({id, ComponentMask(3, true), exact_ptr, {}});
        elasticity.setup(conditions);
        elasticity.loads().body_force = &force;
        solve_linear(elasticity);
        const auto [l2, h1] = elasticity.field().errors(exact);

        std::ostringstream line;
        line << "level " << level << " dofs " << std::setw(7)
             << elasticity.field().dof_handler().n_dofs() << std::scientific
             << std::setprecision(3) << "  L2 " << l2 << "  H1 " << h1;
        if (level > 0)
          line << std::fixed << std::setprecision(2) << "  rate L2 "
               << std::log2(last_l2 / l2) << "  rate H1 "
               << std::log2(last_h1 / h1);
        deallog << line.str() << std::endl;
        last_l2 = l2;
        last_h1 = h1;
      }
  }
} // namespace ssc_test

#endif
