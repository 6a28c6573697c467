// Elastic disk of radius R touching the wall plane x = 0.
//
// The disk is centred at (R, 0), so it touches the wall at the contact point
// (0, 0), which is a geometry point and therefore always a mesh vertex. The
// mesh is refined toward the contact point and consists of quadrilaterals only.
//
// Parameters (change with -setnumber NAME VALUE):
//   R               disk radius                                    (default 1)
//   half            0: full disk, 1: upper half disk y >= 0 only   (default 0)
//   h_far           element size far from the contact point        (default 0.15*R)
//   h_contact       element size at the contact point              (default 0.01*R)
//   grading_radius  distance from the contact point over which the
//                   size grows from h_contact to h_far             (default 0.5*R)
//   subdivide       0: full-quad recombination, 1: recombination plus
//                   subdivision (fallback, see the end of the file) (default 0)
//
// Boundary-id convention (physical groups):
//   curve 1   "curved boundary"  all circular arcs
//   curve 2   "symmetry line"    the diameter on y = 0 (half disk only)
//   surface 1 "disk"
//
// Meshing:
//   gmsh -2 meshes/disk.geo -o disk.msh
//   gmsh -2 meshes/disk.geo -setnumber half 1 -setnumber h_contact 0.005 -o half_disk.msh

// DefineConstant (rather than DefineNumber) lets -setnumber override the
// defaults; the defaults of the sizes scale with R.
DefineConstant[
  R = {1, Name "Parameters/R"}
  half = {0, Choices{0, 1}, Name "Parameters/half"}
  h_far = {0.15 * R, Name "Parameters/h_far"}
  h_contact = {0.01 * R, Name "Parameters/h_contact"}
  grading_radius = {0.5 * R, Name "Parameters/grading_radius"}
  subdivide = {0, Choices{0, 1}, Name "Parameters/subdivide"}
];

Mesh.MshFileVersion = 2.2;

// Centre, contact point and the other points on the circle (the sizes come
// from the field below).
Point(1) = {R, 0, 0};
Point(2) = {0, 0, 0};  // contact point
Point(3) = {R, R, 0};
Point(4) = {2 * R, 0, 0};

// Upper quarter arcs (0,0) -> (R,R) -> (2R,0).
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};

// The curve loops are traversed in reverse so that the surface, and hence
// every quadrilateral, is oriented counter-clockwise.
If (half == 0)
  // Lower quarter arcs (2R,0) -> (R,-R) -> (0,0).
  Point(5) = {R, -R, 0};
  Circle(3) = {4, 1, 5};
  Circle(4) = {5, 1, 2};
  Curve Loop(1) = {-4, -3, -2, -1};
  Physical Curve("curved boundary", 1) = {1, 2, 3, 4};
Else
  Line(3) = {4, 2};  // diameter (2R,0) -> (0,0) on y = 0
  Curve Loop(1) = {-3, -2, -1};
  Physical Curve("curved boundary", 1) = {1, 2};
  Physical Curve("symmetry line", 2) = {3};
EndIf

Plane Surface(1) = {1};
Physical Surface("disk", 1) = {1};

// Size field: h_contact at the contact point, growing to h_far over
// grading_radius.
Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_contact;
Field[2].SizeMax = h_far;
Field[2].DistMin = 0;
Field[2].DistMax = grading_radius;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

// All-quadrilateral mesh: Frontal-Delaunay triangles, recombined with the
// "simple full-quad" algorithm, then smoothed. This needs an even number of
// edges on each curve; with a steep grading (grading_radius close to h_far)
// gmsh 4.8 may fail with "1D mesh cannot be divided by 2". Then use
// -setnumber subdivide 1: Blossom recombination followed by splitting every
// element into quadrilaterals (always succeeds, angles are usually worse);
// the size field is doubled beforehand so h_far and h_contact keep their
// meaning. Mesh.Algorithm = 8 (Frontal-Delaunay for quads) is not used
// because it crashes (segmentation fault) with the Debian gmsh 4.8.4 build.
Recombine Surface{1};
Mesh.Algorithm = 6;
Mesh.Smoothing = 10;
If (subdivide == 0)
  Mesh.RecombinationAlgorithm = 2;
Else
  Mesh.RecombinationAlgorithm = 1;
  Mesh.SubdivisionAlgorithm = 1;
  Mesh.MeshSizeFactor = 2;
EndIf
