// A 2D plate, 40 mm x 20 mm, with a central hole of radius 4 mm, meshed with quadrangles of
// about 1 mm. Physical groups: the surface "plate" (the block), the curves "left" and "right"
// (node sets, grown in the deck into layers a horizon thick).
SetFactory("OpenCASCADE");
Rectangle(1) = {-0.02, -0.01, 0, 0.04, 0.02};
Disk(2) = {0, 0, 0, 0.004};
BooleanDifference(3) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
Physical Surface("plate") = {3};
Physical Curve("left") = {Curve In BoundingBox{-0.0201, -0.0101, -1, -0.0199, 0.0101, 1}};
Physical Curve("right") = {Curve In BoundingBox{0.0199, -0.0101, -1, 0.0201, 0.0101, 1}};
Mesh.CharacteristicLengthMin = 0.001;
Mesh.CharacteristicLengthMax = 0.001;
Mesh.RecombineAll = 1;
