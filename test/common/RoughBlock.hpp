#pragma once
// A 5^3 (or, planar, 5^2) block of points, horizon 2.01 spacings, under a rough initial
// displacement, without its Solver list: the scene where the implicit tangents are compared with
// column differences (test_quasistatic.cpp, test_fd_tangent.cpp). `material` is the body of the
// material list (Material Model and constants, 6-space indented lines).
#include <sstream>
#include <string>

namespace peridot {
namespace testing {

inline std::string roughBlockProblem(const std::string& material, bool planar) {
  const int n = 5, count = planar ? n * n : n * n * n;
  std::ostringstream d;
  d << "Peridigm:\n  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n";
  if (planar) {
    d << "    Thickness: 0.5\n    TensorProduct2DMeshGenerator:\n"
         "      X Origin: 0.0\n      Y Origin: 0.0\n      X Length: 5.0\n      Y Length: 5.0\n"
         "      Number Points X: 5\n      Number Points Y: 5\n";
  } else {
    d << "    TensorProduct3DMeshGenerator:\n"
         "      X Origin: 0.0\n      Y Origin: 0.0\n      Z Origin: 0.0\n"
         "      X Length: 5.0\n      Y Length: 5.0\n      Z Length: 5.0\n"
         "      Number Points X: 5\n      Number Points Y: 5\n      Number Points Z: 5\n";
  }
  d << "  Materials:\n    M:\n"
    << material
    << "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 2.01\n"
       "  Boundary Conditions:\n    All Node Set: \"";
  for (int i = 1; i <= count; ++i) d << i << (i < count ? " " : "");
  d << "\"\n";
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < (planar ? 2 : 3); ++a) {
    d << "    U" << axes[a] << ":\n      Type: Initial Displacement\n      Node Set: All Node Set\n"
      << "      Coordinate: " << axes[a] << "\n      Value: \"0.05*sin(" << 1.3 + a
      << "*x + 2.1*y*y + 0.7*z*x + " << a << ")\"\n";
  }
  return d.str();
}

}  // namespace testing
}  // namespace peridot
