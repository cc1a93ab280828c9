// Paper 000's bar (V3): 500 m x 4 m x 4 m, meshed with tetrahedra of size about h by Gmsh's
// Delaunay mesher; Peridot puts one point at each tetrahedron's centroid with its volume.
//   gmsh -3 bar.geo -setnumber h 1.0 -setnumber L 500 -format msh41 -o bar.msh
// Quality optimisation is off so that the cells keep the spread of sizes and shapes the
// Delaunay mesher gives (the paper's mesh was deliberately irregular).
DefineConstant[ h = 1.0, L = 500.0 ];
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, L, 4, 4};
Physical Volume("bar") = {1};
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
Mesh.Optimize = 0;
