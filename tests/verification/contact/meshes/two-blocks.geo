// Source of two-blocks.msh: two 4 x 4 x 2 mm blocks stacked along z, touching on the plane z = 2
// but not joined (each has its own nodes there), meshed with different element sizes (1 mm below,
// 0.7 mm above), so the two faces of the interface do not match.
// Regenerate with:  gmsh -3 -format msh22 two-blocks.geo -o two-blocks.msh
//              and:  gmsh -3 -order 2 -format msh22 two-blocks.geo -o two-blocks-order2.msh
// (the second-order mesh, for the Taylor-Hood element)
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 4, 4, 2};
Box(2) = {0, 0, 2, 4, 4, 2};
lower() = Boundary{Volume{1};};  // x = 0, x = 4, y = 0, y = 4, z = 0, z = 2
upper() = Boundary{Volume{2};};  // x = 0, x = 4, y = 0, y = 4, z = 2, z = 4
MeshSize{ PointsOf{Volume{1};} } = 1.0;
MeshSize{ PointsOf{Volume{2};} } = 0.7;
Physical Surface("base") = {lower(4)};
Physical Surface("lower_top") = {lower(5)};
Physical Surface("upper_bottom") = {upper(4)};
Physical Surface("top") = {upper(5)};
Physical Surface("sym_x") = {lower(0), upper(0)};
Physical Surface("sym_y") = {lower(2), upper(2)};
Physical Volume("lower") = {1};
Physical Volume("upper") = {2};
