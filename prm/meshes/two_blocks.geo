// Two blocks for the 'gmsh' scene of dyncontact: a lower block [0,2]x[-0.5,0]
// and an upper block [0.7,1.3]x[0.05,0.35], separate (no shared points), with
// quadrilateral cells. Physical tags: surfaces 1 (lower) and 2 (upper);
// lines 10 (bottom of the lower block), 11 (top of the lower block), 12
// (bottom of the upper block), 13 (top of the upper block).
// Regenerate: gmsh -2 -format msh22 two_blocks.geo -o two_blocks.msh
h = 0.05;
Point(1) = {0, -0.5, 0, h};
Point(2) = {2, -0.5, 0, h};
Point(3) = {2, 0, 0, h};
Point(4) = {0, 0, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 41;
Transfinite Curve{2, 4} = 11;
Transfinite Surface{1};
Recombine Surface{1};

Point(5) = {0.7, 0.05, 0, h};
Point(6) = {1.3, 0.05, 0, h};
Point(7) = {1.3, 0.35, 0, h};
Point(8) = {0.7, 0.35, 0, h};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};
Transfinite Curve{5, 7} = 17;
Transfinite Curve{6, 8} = 9;
Transfinite Surface{2};
Recombine Surface{2};

Physical Surface(1) = {1};
Physical Surface(2) = {2};
Physical Curve(10) = {1};
Physical Curve(11) = {3};
Physical Curve(12) = {5};
Physical Curve(13) = {7};
