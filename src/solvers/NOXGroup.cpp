#include "solvers/NOXGroup.hpp"

namespace peridot {

namespace {
const TpetraVector& tv(const NOX::Abstract::Vector& v) {
  return dynamic_cast<const NOXVector&>(v).tpetra();
}
TpetraVector& tv(NOX::Abstract::Vector& v) { return dynamic_cast<NOXVector&>(v).tpetra(); }
}  // namespace

NOXGroup::NOXGroup(NOXProblem& problem, const NOXVector& x)
    : problem_(&problem),
      x_(Teuchos::rcp(new NOXVector(x, NOX::DeepCopy))),
      f_(Teuchos::rcp(new NOXVector(x, NOX::ShapeCopy))),
      gradient_(Teuchos::rcp(new NOXVector(x, NOX::ShapeCopy))),
      newton_(Teuchos::rcp(new NOXVector(x, NOX::ShapeCopy))) {}

NOXGroup::NOXGroup(const NOXGroup& source, NOX::CopyType type)
    : problem_(source.problem_),
      x_(Teuchos::rcp(new NOXVector(*source.x_, type))),
      f_(Teuchos::rcp(new NOXVector(*source.f_, type))),
      gradient_(Teuchos::rcp(new NOXVector(*source.gradient_, type))),
      newton_(Teuchos::rcp(new NOXVector(*source.newton_, type))) {
  if (type == NOX::DeepCopy) {
    normF_ = source.normF_;
    isF_ = source.isF_;
    isGradient_ = source.isGradient_;
    isNewton_ = source.isNewton_;
    linearization_ = source.linearization_;
  }
}

NOX::Abstract::Group& NOXGroup::operator=(const NOX::Abstract::Group& source) {
  const auto& s = dynamic_cast<const NOXGroup&>(source);
  if (&s == this) return *this;
  problem_ = s.problem_;
  *x_ = *s.x_;
  *f_ = *s.f_;
  *gradient_ = *s.gradient_;
  *newton_ = *s.newton_;
  normF_ = s.normF_;
  isF_ = s.isF_;
  isGradient_ = s.isGradient_;
  isNewton_ = s.isNewton_;
  linearization_ = s.linearization_;
  return *this;
}

void NOXGroup::reset() {
  isF_ = isGradient_ = isNewton_ = false;
  linearization_ = 0;
}

void NOXGroup::setX(const NOX::Abstract::Vector& y) {
  reset();
  *x_ = y;
}

void NOXGroup::computeX(const NOX::Abstract::Group& grp, const NOX::Abstract::Vector& d,
                        double step) {
  reset();
  x_->update(1.0, grp.getX(), step, d, 0.0);
}

NOX::Abstract::Group::ReturnType NOXGroup::computeF() {
  if (isF_) return Ok;
  problem_->computeResidual(x_->tpetra(), f_->tpetra());
  normF_ = f_->norm();
  isF_ = true;
  return Ok;
}

bool NOXGroup::isJacobian() const {
  return linearization_ != 0 && linearization_ == problem_->linearization();
}

NOX::Abstract::Group::ReturnType NOXGroup::ensureLinearization() const {
  if (isJacobian()) return Ok;
  if (!isF_) return BadDependency;
  linearization_ = problem_->linearize(x_->tpetra(), f_->tpetra());
  return Ok;
}

NOX::Abstract::Group::ReturnType NOXGroup::computeJacobian() {
  if (!isF_) computeF();
  return ensureLinearization();
}

NOX::Abstract::Group::ReturnType NOXGroup::computeGradient() {
  // The gradient of 1/2 ||F||^2: J^T F.
  if (isGradient_) return Ok;
  if (!isF_ || ensureLinearization() != Ok) return BadDependency;
  problem_->applyJacobian(f_->tpetra(), gradient_->tpetra(), true);
  isGradient_ = true;
  return Ok;
}

NOX::Abstract::Group::ReturnType NOXGroup::computeNewton(Teuchos::ParameterList& params) {
  if (isNewton_) return Ok;
  if (!isF_ || ensureLinearization() != Ok) return BadDependency;
  const double tolerance = params.get("Tolerance", 1e-4);
  const bool converged = problem_->solveJacobian(f_->tpetra(), newton_->tpetra(), tolerance);
  newton_->scale(-1.0);
  isNewton_ = true;
  return converged ? Ok : NotConverged;
}

NOX::Abstract::Group::ReturnType NOXGroup::applyJacobian(const NOX::Abstract::Vector& input,
                                                         NOX::Abstract::Vector& result) const {
  if (ensureLinearization() != Ok) return BadDependency;
  problem_->applyJacobian(tv(input), tv(result), false);
  return Ok;
}

NOX::Abstract::Group::ReturnType NOXGroup::applyJacobianTranspose(
    const NOX::Abstract::Vector& input, NOX::Abstract::Vector& result) const {
  if (ensureLinearization() != Ok) return BadDependency;
  problem_->applyJacobian(tv(input), tv(result), true);
  return Ok;
}

NOX::Abstract::Group::ReturnType NOXGroup::applyJacobianInverse(
    Teuchos::ParameterList& params, const NOX::Abstract::Vector& input,
    NOX::Abstract::Vector& result) const {
  if (ensureLinearization() != Ok) return BadDependency;
  const double tolerance = params.get("Tolerance", 1e-4);
  return problem_->solveJacobian(tv(input), tv(result), tolerance) ? Ok : NotConverged;
}

NOX::Abstract::Group::ReturnType NOXGroup::applyRightPreconditioning(
    bool, Teuchos::ParameterList&, const NOX::Abstract::Vector& input,
    NOX::Abstract::Vector& result) const {
  problem_->applyPreconditioner(x_->tpetra(), tv(input), tv(result));
  return Ok;
}

Teuchos::RCP<NOX::Abstract::Group> NOXGroup::clone(NOX::CopyType type) const {
  return Teuchos::rcp(new NOXGroup(*this, type));
}

}  // namespace peridot
