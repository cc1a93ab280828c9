#pragma once
// NOX's abstract group for Peridot's static problem: x is the owned displacement (prescribed
// components held at the load step's values), F(x) = V (f + b) with the held components zeroed
// (Peridigm's residual), J = dF/dx = -K (K the stiffness: the tangent of solvers/Tangent.hpp or
// a matrix-free product). The group only caches vectors and flags; the evaluations are done by
// the solver behind NOXProblem, which all clones of a group share.
#include <NOX_Abstract_Group.H>

#include "solvers/NOXVector.hpp"

namespace peridot {

// What a group asks of the solver. Linearizations are numbered; a group's Jacobian is valid
// while the solver's current linearization is the one the group made.
class NOXProblem {
 public:
  virtual ~NOXProblem() = default;
  virtual void computeResidual(const TpetraVector& x, TpetraVector& f) = 0;
  // Linearizes at x (whose residual is f); returns the linearization's number.
  virtual long long linearize(const TpetraVector& x, const TpetraVector& f) = 0;
  virtual long long linearization() const = 0;
  // out = J in (or J^T in) at the current linearization.
  virtual void applyJacobian(const TpetraVector& in, TpetraVector& out, bool transpose) = 0;
  // out = J^-1 in at the current linearization, to the relative `tolerance`; false when the
  // Krylov solver did not converge.
  virtual bool solveJacobian(const TpetraVector& in, TpetraVector& out, double tolerance) = 0;
  // out = M^-1 in, M a preconditioner of J near x (identity without one).
  virtual void applyPreconditioner(const TpetraVector& x, const TpetraVector& in,
                                   TpetraVector& out) = 0;
};

class NOXGroup : public NOX::Abstract::Group {
 public:
  NOXGroup(NOXProblem& problem, const NOXVector& x);
  NOXGroup(const NOXGroup& source, NOX::CopyType type);

  NOX::Abstract::Group& operator=(const NOX::Abstract::Group& source) override;
  void setX(const NOX::Abstract::Vector& y) override;
  void computeX(const NOX::Abstract::Group& grp, const NOX::Abstract::Vector& d,
                double step) override;
  ReturnType computeF() override;
  ReturnType computeJacobian() override;
  ReturnType computeGradient() override;
  ReturnType computeNewton(Teuchos::ParameterList& params) override;
  ReturnType applyJacobian(const NOX::Abstract::Vector& input,
                           NOX::Abstract::Vector& result) const override;
  ReturnType applyJacobianTranspose(const NOX::Abstract::Vector& input,
                                    NOX::Abstract::Vector& result) const override;
  ReturnType applyJacobianInverse(Teuchos::ParameterList& params,
                                  const NOX::Abstract::Vector& input,
                                  NOX::Abstract::Vector& result) const override;
  ReturnType applyRightPreconditioning(bool useTranspose, Teuchos::ParameterList& params,
                                       const NOX::Abstract::Vector& input,
                                       NOX::Abstract::Vector& result) const override;
  bool isF() const override { return isF_; }
  bool isJacobian() const override;
  bool isGradient() const override { return isGradient_; }
  bool isNewton() const override { return isNewton_; }
  const NOX::Abstract::Vector& getX() const override { return *x_; }
  const NOX::Abstract::Vector& getF() const override { return *f_; }
  double getNormF() const override { return normF_; }
  const NOX::Abstract::Vector& getGradient() const override { return *gradient_; }
  const NOX::Abstract::Vector& getNewton() const override { return *newton_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getXPtr() const override { return x_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getFPtr() const override { return f_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getGradientPtr() const override { return gradient_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getNewtonPtr() const override { return newton_; }
  Teuchos::RCP<NOX::Abstract::Group> clone(NOX::CopyType type = NOX::DeepCopy) const override;

 private:
  void reset();
  // Makes this group's linearization the solver's current one (re-linearizing if another
  // group's came after it).
  ReturnType ensureLinearization() const;
  NOXProblem* problem_;
  Teuchos::RCP<NOXVector> x_, f_, gradient_, newton_;
  double normF_ = 0;
  bool isF_ = false, isGradient_ = false, isNewton_ = false;
  mutable long long linearization_ = 0;  // 0: none
};

}  // namespace peridot
