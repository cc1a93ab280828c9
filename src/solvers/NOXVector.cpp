#include "solvers/NOXVector.hpp"

#include <cmath>
#include <ostream>

namespace peridot {

NOXVector::NOXVector(const Teuchos::RCP<const Map>& map)
    : v_(Teuchos::rcp(new TpetraVector(map))) {}

NOXVector::NOXVector(const NOXVector& source, NOX::CopyType type)
    : v_(Teuchos::rcp(new TpetraVector(source.v_->getMap()))) {
  if (type == NOX::DeepCopy) v_->assign(*source.v_);
}

const TpetraVector& NOXVector::of(const NOX::Abstract::Vector& y) {
  return dynamic_cast<const NOXVector&>(y).tpetra();
}

NOX::Abstract::Vector& NOXVector::init(double gamma) {
  v_->putScalar(gamma);
  return *this;
}

NOX::Abstract::Vector& NOXVector::random(bool, int) {
  v_->randomize(-1.0, 1.0);
  return *this;
}

NOX::Abstract::Vector& NOXVector::abs(const NOX::Abstract::Vector& y) {
  v_->abs(of(y));
  return *this;
}

NOX::Abstract::Vector& NOXVector::operator=(const NOX::Abstract::Vector& y) {
  v_->assign(of(y));
  return *this;
}

NOX::Abstract::Vector& NOXVector::reciprocal(const NOX::Abstract::Vector& y) {
  v_->reciprocal(of(y));
  return *this;
}

NOX::Abstract::Vector& NOXVector::scale(double gamma) {
  v_->scale(gamma);
  return *this;
}

NOX::Abstract::Vector& NOXVector::scale(const NOX::Abstract::Vector& a) {
  auto x = v_->getDataNonConst(0);
  const auto w = of(a).getData(0);
  for (LocalOrdinal k = 0; k < static_cast<LocalOrdinal>(x.size()); ++k) x[k] *= w[k];
  return *this;
}

NOX::Abstract::Vector& NOXVector::update(double alpha, const NOX::Abstract::Vector& a,
                                         double gamma) {
  v_->update(alpha, of(a), gamma);
  return *this;
}

NOX::Abstract::Vector& NOXVector::update(double alpha, const NOX::Abstract::Vector& a, double beta,
                                         const NOX::Abstract::Vector& b, double gamma) {
  v_->update(alpha, of(a), beta, of(b), gamma);
  return *this;
}

Teuchos::RCP<NOX::Abstract::Vector> NOXVector::clone(NOX::CopyType type) const {
  return Teuchos::rcp(new NOXVector(*this, type));
}

double NOXVector::norm(NOX::Abstract::Vector::NormType type) const {
  switch (type) {
    case OneNorm:
      return v_->norm1();
    case MaxNorm:
      return v_->normInf();
    default:
      return v_->norm2();
  }
}

double NOXVector::norm(const NOX::Abstract::Vector& weights) const {
  // sqrt(sum w_k x_k^2), NOX's weighted 2-norm.
  const auto x = v_->getData(0);
  const auto w = of(weights).getData(0);
  double local = 0, total = 0;
  for (LocalOrdinal k = 0; k < static_cast<LocalOrdinal>(x.size()); ++k)
    local += w[k] * x[k] * x[k];
  Teuchos::reduceAll(*v_->getMap()->getComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(total));
  return std::sqrt(total);
}

double NOXVector::innerProduct(const NOX::Abstract::Vector& y) const { return v_->dot(of(y)); }

NOX::size_type NOXVector::length() const {
  return static_cast<NOX::size_type>(v_->getGlobalLength());
}

void NOXVector::print(std::ostream& stream) const {
  const auto x = v_->getData(0);
  for (LocalOrdinal k = 0; k < static_cast<LocalOrdinal>(x.size()); ++k) stream << x[k] << " ";
  stream << "\n";
}

}  // namespace peridot
