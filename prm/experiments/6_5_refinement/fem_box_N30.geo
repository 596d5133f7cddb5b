// FEM box 4 x 1 m of BFEMP Section 6.5 for N = 30 (dx = 1/N): 4N x N squares,
// each split into two triangles with alternating diagonals (mirror-symmetric
// about x = 2). Written by doc/experiments/make_refinement_prms.py.
N = 30;
Point(1) = {0, 0, 0};
Point(2) = {4, 0, 0};
Point(3) = {4, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 4 * N + 1;
Transfinite Curve{2, 4} = N + 1;
Transfinite Surface{1} = {1, 2, 3, 4} Alternate;
