// Source of hex_cube.msh: a unit cube meshed with 2 x 2 x 2 hexahedra, which plisse must refuse.
// Regenerate with:  gmsh -3 -format msh22 hex_cube.geo -o hex_cube.msh
Point(1) = {0, 0, 0, 1};
Extrude {1, 0, 0} { Point{1}; Layers{2}; Recombine; }
Extrude {0, 1, 0} { Line{1}; Layers{2}; Recombine; }
Extrude {0, 0, 1} { Surface{5}; Layers{2}; Recombine; }
Physical Volume("body") = {1};
