#pragma once
// NOX's abstract vector on a Tpetra vector of the owned displacement unknowns (3 per point):
// what NOX's directions, line searches and status tests compute with. Reductions (norms, inner
// products) are Tpetra's: sums of the ranks' partial sums, so their last bits depend on the
// partition.
#include <NOX_Abstract_Vector.H>

#include <Tpetra_Vector.hpp>

#include "parallel/Topology.hpp"

namespace peridot {

using TpetraVector = Tpetra::Vector<double, LocalOrdinal, GlobalOrdinal>;

class NOXVector : public NOX::Abstract::Vector {
 public:
  explicit NOXVector(const Teuchos::RCP<const Map>& map);
  NOXVector(const NOXVector& source, NOX::CopyType type = NOX::DeepCopy);
  TpetraVector& tpetra() { return *v_; }
  const TpetraVector& tpetra() const { return *v_; }

  NOX::Abstract::Vector& init(double gamma) override;
  NOX::Abstract::Vector& random(bool useSeed = false, int seed = 1) override;
  NOX::Abstract::Vector& abs(const NOX::Abstract::Vector& y) override;
  NOX::Abstract::Vector& operator=(const NOX::Abstract::Vector& y) override;
  // A deep copy of the values (never a shared Tpetra vector).
  NOXVector& operator=(const NOXVector& y) {
    v_->assign(*y.v_);
    return *this;
  }
  NOX::Abstract::Vector& reciprocal(const NOX::Abstract::Vector& y) override;
  NOX::Abstract::Vector& scale(double gamma) override;
  NOX::Abstract::Vector& scale(const NOX::Abstract::Vector& a) override;
  NOX::Abstract::Vector& update(double alpha, const NOX::Abstract::Vector& a,
                                double gamma = 0.0) override;
  NOX::Abstract::Vector& update(double alpha, const NOX::Abstract::Vector& a, double beta,
                                const NOX::Abstract::Vector& b, double gamma = 0.0) override;
  Teuchos::RCP<NOX::Abstract::Vector> clone(NOX::CopyType type = NOX::DeepCopy) const override;
  double norm(NOX::Abstract::Vector::NormType type = TwoNorm) const override;
  double norm(const NOX::Abstract::Vector& weights) const override;
  double innerProduct(const NOX::Abstract::Vector& y) const override;
  NOX::size_type length() const override;
  void print(std::ostream& stream) const override;

 private:
  static const TpetraVector& of(const NOX::Abstract::Vector& y);
  Teuchos::RCP<TpetraVector> v_;
};

}  // namespace peridot
