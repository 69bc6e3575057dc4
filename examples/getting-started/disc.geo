// disc.geo: a quarter of a circular membrane, radius 20 mm, 0.5 mm thick, tagged for plisse.
//   gmsh -3 -order 2 disc.geo -o disc.msh   (second order, for element: taylor-hood)
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 20};
Rectangle(2) = {0, 0, 0, 25, 25};
BooleanIntersection(3) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
// One layer of prisms through the thickness, each cut into three tetrahedra.
Extrude {0, 0, 0.5} { Surface{3}; Layers{1}; }
e = 1e-3;
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, 21, 21, e};
Physical Surface("top") = Surface In BoundingBox{-e, -e, 0.5 - e, 21, 21, 0.5 + e};
Physical Surface("sym_x") = Surface In BoundingBox{-e, -e, -e, e, 21, 0.5 + e};
Physical Surface("sym_y") = Surface In BoundingBox{-e, -e, -e, 21, e, 0.5 + e};
rim() = Surface{:};
rim() -= Surface In BoundingBox{-e, -e, -e, 21, 21, e};
rim() -= Surface In BoundingBox{-e, -e, 0.5 - e, 21, 21, 0.5 + e};
rim() -= Surface In BoundingBox{-e, -e, -e, e, 21, 0.5 + e};
rim() -= Surface In BoundingBox{-e, -e, -e, 21, e, 0.5 + e};
Physical Surface("rim") = {rim()};
Physical Volume("membrane") = {Volume{:}};
Mesh.MeshSizeMax = 1.0;
