// A plate with a grid of cylindrical through holes (scripts/bench_constrained3d.py, issue 20):
// flat faces and many cylinder seams, the new user's first CAD-like input.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 0.3};
k = 2;
For i In {0:2}
  For j In {0:2}
    Cylinder(k) = {0.2 + 0.3 * i, 0.2 + 0.3 * j, -0.1, 0, 0, 0.5, 0.07 + 0.02 * ((i + j) % 2)};
    k += 1;
  EndFor
EndFor
BooleanDifference{ Volume{1}; Delete; }{ Volume{2:k-1}; Delete; }
