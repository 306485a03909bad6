// Mass-spring strands: edge springs between neighbours and bending springs between particles
// two apart (the edge and bending springs of Selle, Lentine and Fedkiw 2008, without their
// torsion and altitude springs). A straight run of particles therefore resists bending only to
// second order; a straight strand hangs like a chain.
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "sim/solver/baselines/baseline_solver.h"

namespace csm {

// Symplectic (semi-explicit) Euler: v += h f(x) / m, x += h v. Stable only while h stays
// below about 2 / omega_max, with omega_max^2 ~ 4 EA / (density l^2).
class ExplicitMassSpring final : public BaselineSolver {
 public:
  using BaselineSolver::BaselineSolver;
  std::string_view name() const override { return "ms-explicit"; }
  void step(double h, const Pose& head) override;

 private:
  void onReset() override { force_.assign(x_.size(), glm::dvec3(0.0)); }
  std::vector<glm::dvec3> force_;
};

// Backward Euler on the springs, linearised once per step (Baraff and Witkin 1998):
// (M - h^2 K) dv = h (f + h K v), one sparse solve per step for all strands together (the
// matrix is block diagonal per strand and banded within one). Compressed springs drop the
// transverse part of their Jacobian so the matrix stays positive definite (Choi and Ko 2002).
// External forces are explicit.
class ImplicitMassSpring final : public BaselineSolver {
 public:
  using BaselineSolver::BaselineSolver;
  std::string_view name() const override { return "ms-implicit"; }
  void step(double h, const Pose& head) override;

 private:
  void onReset() override;
  Eigen::SparseMatrix<double> A_;
  Eigen::VectorXd b_, dv_;
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>
      solver_;
  bool analysed_ = false;
};

}  // namespace csm
