// BFEMP Section 6.2: the kinematic FEM body whose lower contour is the sine
// wave y = A cos(2 pi x / L) (A = 1/40 m, L = 0.1 m), for x in [0, 2.2] m,
// with a flat top at y = 0.1 m. The prm files place it with the mesh
// 'translation' (offset of the wave) and mesh it at run time with
// gmsh -2 -clmax 'target edge length'.
// The contour is a polyline of 40 segments per wavelength: the largest
// chord sag (at the crests, curvature radius L^2 / (4 pi^2 A) = 10 mm) is
// s^2 / (8 R) = 0.08 mm for segments of s = 2.5 mm, below dhat = 1 mm.
A     = 1 / 40;
L     = 0.1;
x0    = 0;
x1    = 2.2;
top   = 0.1;
n     = 880;     // 40 segments per wavelength over 22 wavelengths
lc    = 0.0025;  // element size on the contour (= the segment length in x)
lcTop = 0.05;    // element size at the flat top (clmax caps it as well)

For i In {0:n}
  x = x0 + (x1 - x0) * i / n;
  Point(i + 1) = {x, A * Cos(2 * Pi * x / L), 0, lc};
EndFor
Point(n + 2) = {x1, top, 0, lcTop};
Point(n + 3) = {x0, top, 0, lcTop};
For i In {1:n}
  Line(i) = {i, i + 1};
EndFor
Line(n + 1) = {n + 1, n + 2};
Line(n + 2) = {n + 2, n + 3};
Line(n + 3) = {n + 3, 1};
Curve Loop(1) = {1:n + 3};
Plane Surface(1) = {1};
Physical Surface(1) = {1};
