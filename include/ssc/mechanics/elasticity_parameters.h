#ifndef ssc_mechanics_elasticity_parameters_h
#define ssc_mechanics_elasticity_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <array>

#include <ssc/base/enum_table.h>
#include <ssc/mechanics/linear_solver_parameters.h>

namespace ssc
{
  using namespace dealii;

  /**
   * Volume discretisation. displacement: standard Galerkin. mixed: the
   * displacement with the dilatation (tr eps at small strain, J at finite
   * strain) L2-projected onto discontinuous P_{p-1} on each cell, i.e. the
   * Q_p-P_{p-1}^disc displacement-pressure method with the pressure
   * condensed out (B-bar; three-field Hu-Washizu at finite strain). mean
   * dilatation: the same with the projection onto constants (Q_p-P0; for
   * Q1 the same as mixed). enhanced (Q1, small strain): mixed plus the
   * Wilson-Taylor incompatible modes, against the shear locking of thin
   * layers in bending.
   */
  enum class Formulation
  {
    displacement,
    mixed,
    mean_dilatation,
    enhanced
  };

  constexpr std::array<std::pair<Formulation, const char *>, 4>
  enum_table(Formulation)
  {
    return {{{Formulation::displacement, "displacement"},
             {Formulation::mixed, "mixed"},
             {Formulation::mean_dilatation, "mean dilatation"},
             {Formulation::enhanced, "enhanced"}}};
  }

  /// How the lateral sides of the patch are held.
  enum class SideCondition
  {
    free,
    roller,
    fixed
  };

  constexpr std::array<std::pair<SideCondition, const char *>, 3>
  enum_table(SideCondition)
  {
    return {{{SideCondition::free, "free"},
             {SideCondition::roller, "roller"},
             {SideCondition::fixed, "fixed"}}};
  }

  /**
   * Discretisation, boundary conditions and linear solver of the volume
   * elasticity problem (section "Elasticity").
   */
  struct ElasticityParameters
  {
    unsigned int  degree      = 1;
    Formulation   formulation = Formulation::displacement;
    SideCondition sides       = SideCondition::roller;
    /// Finite strain, mixed formulations: fraction of the volumetric
    /// energy taken at the quadrature points instead of from the projected
    /// dilatation.
    double                 volumetric_stabilisation = 0.;
    LinearSolverParameters linear_solver;

    /// Dimension of the cell's pressure (dilatation) space: 0 for the
    /// displacement formulation, 1 for P0, 4 for P1 (Q2 mixed).
    unsigned int
    n_pressure_modes() const;

    /// Declares section "Elasticity", bound to the members.
    void
    add_parameters(ParameterHandler &prm);

    /// Checks the values (after parsing); throws naming the parameter.
    void
    check() const;
  };
} // namespace ssc

#endif
