#pragma once
// The implicit solvers' tangent K against central differences of the residual R = V (f + b),
// one column at a time (K = -dR/du): the check of every analytic tangent (test_quasistatic.cpp)
// and of the probed one (test_fd_tangent.cpp).
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "app/Simulation.hpp"
#include "solvers/QuasiStatic.hpp"

namespace peridot {
namespace testing {

// Largest |K - K_column| over the columns of every third point (corner, edge, face and interior
// points among them; two collective evaluations a column), relative to the largest entry of
// either (collective). h = 1e-6 for a point spacing of 1: truncation ~h^2, rounding ~1e-16 |f|/h.
// QuasiStatic's evaluations are trials: no history moves.
inline double tangentAgainstColumns(Simulation& sim, bool planar) {
  QuasiStatic& qs = *sim.quasiStatic();
  const Topology& t = sim.topology();
  double* u = sim.fields().node("Displacement", 3);
  qs.evaluate(0.0);
  qs.assembleTangent();
  const auto A = qs.tangent().matrix();
  const auto colMap = A->getColMap();
  const double h = 1e-6;
  double worst = 0, largest = 0;
  for (long long g = 0; g < t.globalNumPoints; g += 3) {
    for (int d = 0; d < (planar ? 2 : 3); ++d) {
      const GlobalOrdinal column = 3 * g + d;
      const LocalOrdinal owned = t.ownedMap->getLocalElement(g);
      const bool mine = owned != Teuchos::OrdinalTraits<LocalOrdinal>::invalid();
      std::vector<double> plus, minus;
      for (double sign : {1.0, -1.0}) {
        const double saved = mine ? u[3 * owned + d] : 0.0;
        if (mine) u[3 * owned + d] = saved + sign * h;
        qs.evaluate(0.0);
        (sign > 0 ? plus : minus) = qs.residual();
        if (mine) u[3 * owned + d] = saved;
      }
      const LocalOrdinal c = colMap->getLocalElement(column);
      for (int r = 0; r < 3 * t.numOwned; ++r) {
        if (planar && r % 3 == 2) continue;
        double k = 0;
        if (c != Teuchos::OrdinalTraits<LocalOrdinal>::invalid()) {
          CrsMatrix::local_inds_host_view_type cols;
          CrsMatrix::values_host_view_type vals;
          A->getLocalRowView(r, cols, vals);
          for (std::size_t e = 0; e < cols.extent(0); ++e)
            if (cols(e) == c) k = vals(e);
        }
        const double fd = -(plus[r] - minus[r]) / (2 * h);
        worst = std::max(worst, std::fabs(k - fd));
        largest = std::max({largest, std::fabs(k), std::fabs(fd)});
      }
    }
  }
  double global[2] = {worst, largest};
  MPI_Allreduce(MPI_IN_PLACE, global, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_GT(global[1], 0.0);
  return global[0] / global[1];
}

}  // namespace testing
}  // namespace peridot
