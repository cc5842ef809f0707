#ifndef ssc_mechanics_cell_pressure_block_h
#define ssc_mechanics_cell_pressure_block_h

#include <deal.II/lac/full_matrix.h>

namespace ssc
{
  using namespace dealii;

  /**
   * The displacement-pressure structure of a cell's tangent in the mixed
   * formulations: K = K_0 + B^T C^{-1} B. B couples the cell's
   * discontinuous pressure modes to its displacement dofs, C (symmetric
   * positive definite) is the pressure block (M / kappa at small strain,
   * M H^{-1} M at finite strain, with the incompatible modes' share for
   * the enhanced formulation), and K_0 holds the rest: the deviatoric,
   * geometric and embedded parts, whose conditioning does not depend on
   * the bulk modulus. The saddle-point system [K_0 B^T; B -C] has the same
   * displacement solution as K and can be preconditioned robustly in nu
   * (PressureSystem, LinearSolver). The kernels give K_0, B, C, the
   * pressure mass matrix M and the shear modulus mu; augment() then moves
   * a volumetric share gamma B^T M^{-1} B of modulus about 8 mu from the
   * pressure into K_0 (K_0 alone is singular for the dilatation, which AMG
   * handles badly) and sets schur, the cell's approximation
   * M / (2 mu + gamma) + C of the Schur complement.
   */
  struct CellPressureBlock
  {
    /// Moves gamma B^T M^{-1} B into K_0, gamma = min(8 mu, 1 / (2 tr(C
    /// M^{-1}))), so that C^{-1} - gamma M^{-1} stays positive definite
    /// (at least half C^{-1}); K_0 + B^T C^{-1} B is unchanged. Sets schur.
    void
    augment();

    /// The pressure space's mass matrix M, n_p x n_p.
    FullMatrix<double> mass;
    /// The shear modulus of the cell's layer.
    double shear_modulus = 0;
    /// K_0, n x n (n displacement dofs of the cell).
    FullMatrix<double> reduced;
    /// B, n_p x n.
    FullMatrix<double> coupling;
    /// C, n_p x n_p.
    FullMatrix<double> pressure;
    /// M / (2 mu + gamma) + C, n_p x n_p (augment()).
    FullMatrix<double> schur;
  };
} // namespace ssc

#endif
