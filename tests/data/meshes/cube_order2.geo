// Source of cube_order2.msh: a unit cube meshed with 10-node tetrahedra (second order, straight
// edges), for tests/unit/mesh. Regenerate with:
//   gmsh -3 -order 2 -format msh41 cube_order2.geo -o cube_order2.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
MeshSize{ PointsOf{ Volume{1}; } } = 0.7;
Mesh.SecondOrderLinear = 1;  // edge nodes at edge midpoints
// Faces of the OCC box: 1 x=0, 2 x=1, 3 y=0, 4 y=1, 5 z=0, 6 z=1.
Physical Surface("left") = {1};
Physical Surface("top") = {6};
Physical Surface(7) = {2};  // unnamed: read as "2:7"
Physical Volume("body") = {1};
