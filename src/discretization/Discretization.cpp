#include "discretization/Discretization.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/Error.hpp"
#include "core/Format.hpp"
#include "deck/Expression.hpp"
#include "discretization/DistributedExodusReader.hpp"
#include "discretization/GmshReader.hpp"
#include "discretization/Slicing.hpp"
#include "discretization/TextMeshReader.hpp"

namespace peridot {

namespace {

const double kPi = 3.14159265358979323846;

void readVector3(ListReader& r, const std::string& prefix, double* out, bool required,
                 const char* suffixes = "XYZ") {
  for (int d = 0; d < 3; ++d) {
    const std::string key = prefix + suffixes[d];
    out[d] = required ? r.number(key) : r.number(key, out[d]);
  }
}

}  // namespace

BondFilter readBondFilter(ListReader r, const std::string& name) {
  BondFilter f;
  f.name = name;
  const std::string type = r.choice("Type", {"Rectangular_Plane", "Disk", "Exodus Mesh"});
  if (type == "Exodus Mesh") {
    f.kind = BondFilter::Kind::ExodusMesh;
    const std::string file = r.string("File Name");
    f.facets = std::make_shared<FacetMesh>(FacetMesh::read(file, r.pathOf("File Name")));
    r.finish();
    return f;
  }
  if (type == "Rectangular_Plane") {
    f.kind = BondFilter::Kind::RectangularPlane;
    readVector3(r, "Normal_", f.normal, true);
    readVector3(r, "Lower_Left_Corner_", f.lowerLeftCorner, true);
    readVector3(r, "Bottom_Unit_Vector_", f.bottomUnitVector, true);
    f.bottomLength = r.positiveNumber("Bottom_Length");
    f.sideLength = r.positiveNumber("Side_Length");
  } else {
    f.kind = BondFilter::Kind::Disk;
    readVector3(r, "Center_", f.center, true);
    readVector3(r, "Normal_", f.normal, true);
    f.radius = r.positiveNumber("Radius");
  }
  const double n =
      std::sqrt(f.normal[0] * f.normal[0] + f.normal[1] * f.normal[1] + f.normal[2] * f.normal[2]);
  if (!(n > 0)) throw InputError(r.path(), "the normal vector must not be zero");
  for (double& c : f.normal) c /= n;
  if (f.kind == BondFilter::Kind::RectangularPlane) {
    const double b = std::sqrt(f.bottomUnitVector[0] * f.bottomUnitVector[0] +
                               f.bottomUnitVector[1] * f.bottomUnitVector[1] +
                               f.bottomUnitVector[2] * f.bottomUnitVector[2]);
    if (!(b > 0)) throw InputError(r.path(), "the bottom unit vector must not be zero");
    for (double& c : f.bottomUnitVector) c /= b;
  }
  r.finish();
  return f;
}

bool BondFilter::cuts(const double* p, const double* q) const {
  // The same answer from either end: a bond is in both ends' lists or in neither (the search
  // asks from each end; a cut seen from one end only would leave a one-sided bond). The ends are
  // taken in one fixed order, so the rounding of the test below is the same both ways.
  if (std::lexicographical_compare(q, q + 3, p, p + 3)) std::swap(p, q);
  if (kind == Kind::ExodusMesh) return facets->cuts(p, q);
  const double* origin = kind == Kind::Disk ? center : lowerLeftCorner;
  const double dp = (p[0] - origin[0]) * normal[0] + (p[1] - origin[1]) * normal[1] +
                    (p[2] - origin[2]) * normal[2];
  const double dq = (q[0] - origin[0]) * normal[0] + (q[1] - origin[1]) * normal[1] +
                    (q[2] - origin[2]) * normal[2];
  // Both ends strictly on one side: no crossing. A bond lying in the plane is not cut.
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) return false;
  const double t = dp / (dp - dq);
  double hit[3];
  for (int d = 0; d < 3; ++d) hit[d] = p[d] + t * (q[d] - p[d]) - origin[d];
  if (kind == Kind::Disk) {
    return hit[0] * hit[0] + hit[1] * hit[1] + hit[2] * hit[2] <= radius * radius;
  }
  // side direction = normal x bottom
  const double side[3] = {normal[1] * bottomUnitVector[2] - normal[2] * bottomUnitVector[1],
                          normal[2] * bottomUnitVector[0] - normal[0] * bottomUnitVector[2],
                          normal[0] * bottomUnitVector[1] - normal[1] * bottomUnitVector[0]};
  const double a =
      hit[0] * bottomUnitVector[0] + hit[1] * bottomUnitVector[1] + hit[2] * bottomUnitVector[2];
  const double b = hit[0] * side[0] + hit[1] * side[1] + hit[2] * side[2];
  return a >= 0 && a <= bottomLength && b >= 0 && b <= sideLength;
}

// `Periodic Box Deformation Gradient XX` ... `ZZ`: numbers or expressions in t, the identity
// where absent; all nine are kept when any is given.
void readBoxDeformation(ListReader& r, PeriodicBox& box) {
  const char* axes[3] = {"X", "Y", "Z"};
  std::vector<std::string> sources(9);
  bool any = false;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const std::string key = std::string("Periodic Box Deformation Gradient ") + axes[a] + axes[b];
      if (r.has(key)) {
        sources[3 * a + b] = r.numberOrExpression(key);
        Expression check(sources[3 * a + b], {"t"}, r.pathOf(key));
        if (!any) box.deformationPath = r.pathOf(key);
        any = true;
      } else {
        sources[3 * a + b] = a == b ? "1" : "0";
      }
    }
  if (any) box.deformation = sources;
}

DiscretizationConfig readDiscretizationConfig(ListReader r) {
  DiscretizationConfig c;
  c.type = r.choice("Type", {"Exodus", "Gmsh", "Text File", "PdQuickGrid"});
  if (r.has("Horizon")) {
    throw InputError(r.pathOf("Horizon"),
                     "the horizon belongs in the Blocks section (Blocks -> <group> -> Horizon)");
  }
  if (c.type == "Exodus" || c.type == "Text File" || c.type == "Gmsh") {
    c.meshFile = r.string("Input Mesh File");
    c.meshFilePath = r.pathOf("Input Mesh File");
    if (c.meshFile.empty()) throw InputError(c.meshFilePath, "the file name is empty");
    c.dimension = c.type == "Text File" ? 3 : 0;
  } else {
    const bool box = r.isSublist("TensorProduct3DMeshGenerator");
    const bool box2 = r.isSublist("TensorProduct2DMeshGenerator");
    const bool cyl = r.isSublist("TensorProductCylinderMeshGenerator");
    if (int(box) + int(box2) + int(cyl) != 1) {
      throw InputError(
          r.path(),
          "PdQuickGrid needs exactly one of the sublists TensorProduct3DMeshGenerator, "
          "TensorProduct2DMeshGenerator and TensorProductCylinderMeshGenerator");
    }
    if (box || box2) {
      // The 2D generator is the 3D one without its z axis: cells in the plane z = 0.
      const int axesUsed = box ? 3 : 2;
      ListReader g =
          r.sublist(box ? "TensorProduct3DMeshGenerator" : "TensorProduct2DMeshGenerator");
      c.generatorPath = g.path();
      c.generator = box ? DiscretizationConfig::Generator::TensorProduct3D
                        : DiscretizationConfig::Generator::TensorProduct2D;
      c.dimension = axesUsed;
      if (g.has("Type")) g.choice("Type", {"PdQuickGrid"});
      const char* axes[3] = {"X", "Y", "Z"};
      for (int d = 0; d < axesUsed; ++d) {
        c.origin[d] = g.number(std::string(axes[d]) + " Origin");
        c.length[d] = g.positiveNumber(std::string(axes[d]) + " Length");
        c.numPoints[d] = g.integer(std::string("Number Points ") + axes[d]);
        if (c.numPoints[d] < 1) {
          throw InputError(g.pathOf(std::string("Number Points ") + axes[d]),
                           "expected a positive integer, got " + std::to_string(c.numPoints[d]));
        }
      }
      if (axesUsed == 2) c.numPoints[2] = 1;  // one layer, of zero extent
      const double total = static_cast<double>(c.numPoints[0]) * c.numPoints[1] * c.numPoints[2];
      if (total > INT_MAX) {
        std::string counts =
            std::to_string(c.numPoints[0]) + " x " + std::to_string(c.numPoints[1]);
        if (axesUsed == 3) counts += " x " + std::to_string(c.numPoints[2]);
        throw InputError(g.path(), "too many points (" + counts + "); at most " +
                                       std::to_string(INT_MAX) + " are supported");
      }
      g.finish();
    } else {
      ListReader g = r.sublist("TensorProductCylinderMeshGenerator");
      c.generatorPath = g.path();
      c.generator = DiscretizationConfig::Generator::Cylinder;
      if (g.has("Type")) g.choice("Type", {"PdQuickGrid"});
      c.innerRadius = g.nonNegativeNumber("Inner Radius", 0.0);
      g.accept("Inner Radius");
      c.outerRadius = g.positiveNumber("Outer Radius");
      c.cylinderLength = g.positiveNumber("Cylinder Length");
      c.numRadius = g.integer("Number Points Radius");
      c.ringCenter[0] = g.number("Ring Center x", 0.0);
      c.ringCenter[1] = g.number("Ring Center y", 0.0);
      c.zOrigin = g.number("Z Origin", 0.0);
      if (c.numRadius < 1) {
        throw InputError(g.pathOf("Number Points Radius"), "expected a positive integer");
      }
      if (!(c.outerRadius > c.innerRadius)) {
        throw InputError(g.pathOf("Outer Radius"), "must be larger than the Inner Radius");
      }
      g.finish();
    }
    if (r.has("NeighborhoodType")) {
      r.choice("NeighborhoodType", {"Spherical"});
      c.spherical = true;
    }
  }
  if (r.has("Dimension")) {
    if (c.type != "Text File") {
      throw InputError(r.pathOf("Dimension"),
                       "only for Text File discretizations; the dimension of " +
                           std::string(c.type == "Exodus"
                                           ? "an Exodus mesh is its own (num_dim and element types)"
                                       : c.type == "Gmsh" ? "a Gmsh mesh is that of its cells"
                                                          : "PdQuickGrid is its generator's"));
    }
    c.dimension = static_cast<int>(r.integer("Dimension"));
    if (c.dimension != 2 && c.dimension != 3) {
      throw InputError(r.pathOf("Dimension"),
                       "expected 2 or 3, got " + std::to_string(c.dimension));
    }
  }
  if (r.has("Thickness")) {
    c.thicknessPath = r.pathOf("Thickness");
    c.thickness = r.positiveNumber("Thickness");
    c.thicknessGiven = true;
    // An Exodus mesh's dimension is known once it is read (buildPointCloud checks it then).
    if (c.dimension == 3) {
      throw InputError(c.thicknessPath,
                       "only for 2D discretizations (a TensorProduct2DMeshGenerator, a Text File "
                       "with Dimension: 2, or a planar Exodus mesh); this discretization is 3D");
    }
  }
  if (r.has("Node Set Layers") || r.has("Node Set Layer Depth")) {
    const std::string key = r.has("Node Set Layers") ? "Node Set Layers" : "Node Set Layer Depth";
    if (c.type != "Gmsh") {
      throw InputError(r.pathOf(key), "only for Gmsh discretizations (Type: \"Gmsh\")");
    }
    c.layerSetsPath = r.pathOf("Node Set Layers");
    // Comma-separated, since physical names may hold spaces.
    std::string names = r.string("Node Set Layers");
    std::size_t start = 0;
    while (start <= names.size()) {
      std::size_t comma = names.find(',', start);
      if (comma == std::string::npos) comma = names.size();
      std::string name = names.substr(start, comma - start);
      name.erase(0, name.find_first_not_of(" \t"));
      name.erase(name.find_last_not_of(" \t") + 1);
      if (name.empty()) {
        throw InputError(c.layerSetsPath, "expected physical group names separated by commas");
      }
      c.layerSets.push_back(name);
      start = comma + 1;
    }
    if (r.has("Node Set Layer Depth")) c.layerDepth = r.positiveNumber("Node Set Layer Depth");
  }
  if (r.has("Omit Bonds Between Blocks")) {
    c.omitBondsBetweenBlocks = r.choice("Omit Bonds Between Blocks", {"None", "All"}) == "All";
  }
  c.influenceFunction = r.has("Influence Function") ? r.string("Influence Function") : "One";
  c.partialVolumes = r.has("Partial Volumes") && r.boolean("Partial Volumes", false);
  c.compactBonds = r.choice("Bond Storage", {"Fast", "Compact"}, "Fast") == "Compact";
  // Compact storage is asked for memory: the half list's pairs (4.5 bytes a bond) only on request.
  c.halfBondList = r.boolean("Half Bond List", !c.compactBonds);
  {
    const auto& f = c.influenceFunction;
    if (f != "One" && f != "Parabolic Decay" && f != "Gaussian" && f != "Conical" &&
        f != "Conical Over Zeta") {
      // Anything else is an expression in zeta and horizon: check it now.
      Expression check(f, {"zeta", "horizon"}, r.pathOf("Influence Function"));
    }
  }
  if (r.isSublist("Bond Filters")) {
    if (c.type == "PdQuickGrid") {
      throw InputError(r.pathOf("Bond Filters"),
                       "bond filters are not available with PdQuickGrid (as in Peridigm); use an "
                       "Exodus or Text File discretization");
    }
    ListReader filters = r.sublist("Bond Filters");
    for (const auto& name : filters.keys()) {
      c.bondFilters.push_back(readBondFilter(filters.sublist(name), name));
    }
    filters.finish();
  }
  // Periodic boundaries (a Peridot extension): the box is the generator's, or given.
  const char* axes[3] = {"X", "Y", "Z"};
  for (int d = 0; d < 3; ++d)
    c.periodic.periodic[d] = r.boolean(std::string("Periodic ") + axes[d], false);
  if (c.periodic.periodic[2] && c.dimension == 2) {
    throw InputError(r.pathOf("Periodic Z"), "a 2D discretization has no z extent to repeat");
  }
  if (c.periodic.any()) {
    const bool generatorBox = c.generator == DiscretizationConfig::Generator::TensorProduct3D ||
                              c.generator == DiscretizationConfig::Generator::TensorProduct2D;
    for (int d = 0; d < 3; ++d) {
      const std::string lower = std::string("Periodic Box Lower ") + axes[d];
      const std::string upper = std::string("Periodic Box Upper ") + axes[d];
      if (generatorBox && !r.has(lower) && !r.has(upper)) {
        c.periodic.lower[d] = c.origin[d];
        c.periodic.upper[d] = c.origin[d] + c.length[d];
      } else if (c.periodic.periodic[d]) {
        c.periodic.lower[d] = r.number(lower);
        c.periodic.upper[d] = r.number(upper);
        if (!(c.periodic.upper[d] > c.periodic.lower[d])) {
          throw InputError(r.pathOf(upper),
                           std::string("must be larger than Periodic Box Lower ") + axes[d]);
        }
      } else {
        r.number(lower, 0.0);
        r.number(upper, 0.0);
      }
    }
    if (c.generator == DiscretizationConfig::Generator::Cylinder) {
      throw InputError(r.pathOf("Periodic X"),
                       "periodic boundaries need a box; the cylinder generator has none");
    }
    readBoxDeformation(r, c.periodic);
  }
  for (const char* a : {"X", "Y", "Z"})
    for (const char* b : {"X", "Y", "Z"})
      if (!c.periodic.any() && r.has(std::string("Periodic Box Deformation Gradient ") + a + b)) {
        throw InputError(r.pathOf(std::string("Periodic Box Deformation Gradient ") + a + b),
                         "a deformable periodic box needs a periodic axis (Periodic X, Y or Z)");
      }
  r.boolean("Verbose", false);
  r.boolean("Store Exodus Mesh", false);
  if (r.has("Construct Neighborhood Lists") && !r.boolean("Construct Neighborhood Lists", true)) {
    throw InputError(r.pathOf("Construct Neighborhood Lists"), "false is not supported");
  }
  if (r.has("Compute Element-Horizon Intersections") &&
      r.boolean("Compute Element-Horizon Intersections", false)) {
    throw InputError(r.pathOf("Compute Element-Horizon Intersections"),
                     "not supported by Peridot yet (Peridot does not intersect the mesh's "
                     "elements with the horizon; `Partial Volumes: true` intersects each "
                     "point's cubic cell (edge V^(1/3)) with it, which is the same for a uniform "
                     "axis-aligned grid)");
  }
  if (r.has("Construct Interfaces") && r.boolean("Construct Interfaces", false)) {
    throw InputError(r.pathOf("Construct Interfaces"), "not supported by Peridot yet");
  }
  if (c.partialVolumes && c.generator != DiscretizationConfig::Generator::None &&
      c.generator != DiscretizationConfig::Generator::Cylinder) {
    // The cells of partial volumes are cubes (squares): a generator's spacings must agree.
    const int axes = c.generator == DiscretizationConfig::Generator::TensorProduct2D ? 2 : 3;
    double lo = 1e300, hi = 0;
    for (int d = 0; d < axes; ++d) {
      const double spacing = c.length[d] / static_cast<double>(c.numPoints[d]);
      lo = std::min(lo, spacing);
      hi = std::max(hi, spacing);
    }
    if (hi > lo * (1 + 1e-6)) {
      throw InputError(r.pathOf("Partial Volumes"),
                       "needs cubic cells (square in 2D), but the generator's spacings differ (" +
                           std::to_string(lo) + " to " + std::to_string(hi) + ")");
    }
  }
  r.finish();
  return c;
}

PointCloud readTextMesh(const std::string& fileName, const std::string& deckPath, int dimension,
                        double thickness) {
  return readTextMeshShare(fileName, deckPath, dimension, thickness, MPI_COMM_SELF);
}

namespace {

// The generators number their cells in a fixed order (x fastest, then y, then z, as Peridigm's
// generator does); each rank makes the cells of its contiguous id range [begin, end), computing
// every coordinate from the cell's indices exactly as a whole-grid loop would.
PointCloud tensorProduct(const DiscretizationConfig& c, long long begin, long long end) {
  PointCloud cloud;
  const bool planar = c.generator == DiscretizationConfig::Generator::TensorProduct2D;
  const long long nx = c.numPoints[0], ny = c.numPoints[1];
  const double h[3] = {c.length[0] / nx, c.length[1] / ny,
                       planar ? 0.0 : c.length[2] / c.numPoints[2]};
  // The 2D generator is the 3D one without its z axis: cells in z = 0 whose volume is their area
  // times the thickness.
  const double volume = planar ? h[0] * h[1] * c.thickness : h[0] * h[1] * h[2];
  if (planar) {
    cloud.dimension = 2;
    cloud.thickness = c.thickness;
  }
  const auto n = static_cast<std::size_t>(end - begin);
  cloud.x.reserve(3 * n);
  cloud.volume.assign(n, volume);
  cloud.blockId.assign(n, 1);
  cloud.globalId.resize(n);
  for (long long p = begin; p < end; ++p) {
    const long long i = p % nx, j = (p / nx) % ny, k = p / (nx * ny);
    cloud.x.push_back(c.origin[0] + (i + 0.5) * h[0]);
    cloud.x.push_back(c.origin[1] + (j + 0.5) * h[1]);
    cloud.x.push_back(planar ? 0.0 : c.origin[2] + (k + 0.5) * h[2]);
    cloud.globalId[static_cast<std::size_t>(p - begin)] = p;
  }
  cloud.blockNames[1] = "block_1";
  return cloud;
}

// Rings of cells between the radii: each ring has about as many cells around as makes them
// square in (r, theta); the axial spacing equals the radial one. Radius fastest, then angle, then
// axial layer.
struct CylinderGrid {
  explicit CylinderGrid(const DiscretizationConfig& c)
      : dr((c.outerRadius - c.innerRadius) / c.numRadius),
        nz(std::max<long long>(1, std::llround(c.cylinderLength / dr))),
        dz(c.cylinderLength / nz),
        nTheta(std::max<long long>(
            3, std::llround(2.0 * kPi * (0.5 * (c.innerRadius + c.outerRadius)) / dr))),
        dTheta(2.0 * kPi / nTheta) {}
  double dr;
  long long nz;
  double dz;
  long long nTheta;
  double dTheta;
};

PointCloud tensorProductCylinder(const DiscretizationConfig& c, long long begin, long long end) {
  PointCloud cloud;
  const CylinderGrid g(c);
  for (long long id = begin; id < end; ++id) {
    const long long i = id % c.numRadius, t = (id / c.numRadius) % g.nTheta;
    const long long k = id / (c.numRadius * g.nTheta);
    const double r0 = c.innerRadius + i * g.dr, r1 = r0 + g.dr;
    const double r = 0.5 * (r0 + r1);
    const double theta = (t + 0.5) * g.dTheta;
    cloud.x.push_back(c.ringCenter[0] + r * std::cos(theta));
    cloud.x.push_back(c.ringCenter[1] + r * std::sin(theta));
    cloud.x.push_back(c.zOrigin + (k + 0.5) * g.dz);
    cloud.volume.push_back(0.5 * (r1 * r1 - r0 * r0) * g.dTheta * g.dz);
    cloud.blockId.push_back(1);
    cloud.globalId.push_back(id);
  }
  cloud.blockNames[1] = "block_1";
  return cloud;
}

long long generatorSize(const DiscretizationConfig& c) {
  if (c.generator == DiscretizationConfig::Generator::Cylinder) {
    const CylinderGrid g(c);
    return g.nz * g.nTheta * c.numRadius;
  }
  return c.numPoints[0] * c.numPoints[1] * c.numPoints[2];  // numPoints[2] = 1 in 2D
}

}  // namespace

PointCloud buildWholePointCloud(const DiscretizationConfig& c) {
  // One reader for both: this rank's share when it is the only rank.
  return buildPointCloud(c, MPI_COMM_SELF);
}

PointCloud buildPointCloud(const DiscretizationConfig& c, MPI_Comm comm) {
  if (c.type == "Exodus") {
    PointCloud cloud = readExodusMeshShare(c.meshFile, c.meshFilePath, c.thickness, comm);
    // Keys that depend on the dimension, now that the mesh has told it (the same on every rank).
    if (cloud.dimension == 3 && c.thicknessGiven) {
      throw InputError(c.thicknessPath,
                       "only for 2D discretizations; the Exodus mesh \"" + c.meshFile + "\" is 3D");
    }
    if (cloud.dimension == 2 && c.periodic.periodic[2]) {
      throw InputError(
          "Discretization -> Periodic Z",
          "the Exodus mesh \"" + c.meshFile + "\" is 2D: it has no z extent to repeat");
    }
    return cloud;
  }
  if (c.type == "Gmsh") {
    GmshOptions options;
    options.thickness = c.thickness;
    options.layers = c.layerSets;
    options.layerDepth = c.layerDepth;
    options.layersPath = c.layerSetsPath;
    PointCloud cloud = readGmshMeshShare(c.meshFile, c.meshFilePath, options, comm);
    if (cloud.dimension == 3 && c.thicknessGiven) {
      throw InputError(c.thicknessPath,
                       "only for 2D discretizations; the Gmsh mesh \"" + c.meshFile + "\" is 3D");
    }
    if (cloud.dimension == 2 && c.periodic.periodic[2]) {
      throw InputError("Discretization -> Periodic Z",
                       "the Gmsh mesh \"" + c.meshFile + "\" is 2D: it has no z extent to repeat");
    }
    return cloud;
  }
  if (c.type == "Text File") {
    return readTextMeshShare(c.meshFile, c.meshFilePath, c.dimension, c.thickness, comm);
  }
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const Slicing ids{generatorSize(c), size};
  PointCloud cloud = c.generator == DiscretizationConfig::Generator::Cylinder
                         ? tensorProductCylinder(c, ids.begin(rank), ids.begin(rank + 1))
                         : tensorProduct(c, ids.begin(rank), ids.begin(rank + 1));
  cloud.globalNumPoints = ids.n;
  return cloud;
}

NeighborhoodRule neighborhoodRule(const DiscretizationConfig& c) {
  NeighborhoodRule rule;
  if (c.partialVolumes) {
    rule.kind = NeighborhoodRule::Kind::CellOverlap;  // reach and dimension: buildTopology
    return rule;
  }
  if (c.type != "PdQuickGrid") return rule;
  if (c.spherical || c.generator == DiscretizationConfig::Generator::Cylinder) {
    rule.kind = NeighborhoodRule::Kind::SphereStrict;
    return rule;
  }
  rule.kind = NeighborhoodRule::Kind::CellBox;
  const int axes = c.generator == DiscretizationConfig::Generator::TensorProduct2D ? 2 : 3;
  for (int d = 0; d < axes; ++d) {
    rule.cellSize[d] = c.length[d] / c.numPoints[d];
    rule.cellCount[d] = static_cast<int>(c.numPoints[d]);
  }
  return rule;
}

}  // namespace peridot
