#pragma once
// The bar of test/regression/decks/QuasiStaticBar as a YAML deck without its Solver list: 20 x 4
// x 4 points (10 x 2 x 2), horizon 1.51, end layers (one horizon thick) following the uniaxial
// stress solution u = strain (x, -nu y, -nu z) at t = 1, nu = 0.25. `material` is the body of
// the material list (Material Model and constants, 6-space indented lines).
#include <sstream>
#include <string>

namespace peridot {
namespace testing {

// The bar with its end layers prescribed to the Value expressions `value[0..2]` (x, y, z).
inline std::string staticBarProblemWith(const std::string& material, const std::string value[3]) {
  std::ostringstream left, right;
  int gid = 0;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 20; ++i) {
        ++gid;
        const double x = (i + 0.5) * 0.5;
        if (x < 1.51) left << gid << " ";
        if (x > 10 - 1.51) right << gid << " ";
      }
  std::ostringstream d;
  d << "Peridigm:\n  Discretization:\n    Type: PdQuickGrid\n    NeighborhoodType: Spherical\n"
       "    TensorProduct3DMeshGenerator:\n"
       "      X Origin: 0.0\n      Y Origin: -1.0\n      Z Origin: -1.0\n"
       "      X Length: 10.0\n      Y Length: 2.0\n      Z Length: 2.0\n"
       "      Number Points X: 20\n      Number Points Y: 4\n      Number Points Z: 4\n"
       "  Materials:\n    M:\n"
    << material
    << "  Blocks:\n    B:\n      Block Names: block_1\n      Material: M\n      Horizon: 1.51\n"
       "  Boundary Conditions:\n    Left Node Set: \""
    << left.str() << "\"\n    Right Node Set: \"" << right.str() << "\"\n";
  const char* axes[3] = {"x", "y", "z"};
  for (const char* set : {"Left", "Right"})
    for (int a = 0; a < 3; ++a)
      d << "    " << set << axes[a]
        << ":\n      Type: Prescribed Displacement\n      Node Set: " << set
        << " Node Set\n      Coordinate: " << axes[a] << "\n      Value: \"" << value[a] << "\"\n";
  return d.str();
}

inline std::string staticBarProblem(double strain,
                                    const std::string& material =
                                        "      Material Model: Elastic\n      Density: 7800.0\n"
                                        "      Young's Modulus: 200.0e9\n"
                                        "      Poisson's Ratio: 0.25\n") {
  const char* axes[3] = {"x", "y", "z"};
  const double factor[3] = {strain, -0.25 * strain, -0.25 * strain};
  std::string value[3];
  for (int a = 0; a < 3; ++a) {
    std::ostringstream v;
    v << factor[a] << "*t*" << axes[a];
    value[a] = v.str();
  }
  return staticBarProblemWith(material, value);
}

}  // namespace testing
}  // namespace peridot
