// A pipe flange (issue 20): a disc with a hub, a bore and six bolt holes on a circle.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 0.1, 0.5};
Cylinder(2) = {0, 0, 0, 0, 0, 0.4, 0.25};
BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Cylinder(3) = {0, 0, -0.1, 0, 0, 0.6, 0.18};
BooleanDifference{ Volume{1}; Delete; }{ Volume{3}; Delete; }
For i In {0:5}
  Cylinder(4 + i) = {0.38 * Cos(i * Pi / 3), 0.38 * Sin(i * Pi / 3), -0.1, 0, 0, 0.3, 0.04};
EndFor
BooleanDifference{ Volume{1}; Delete; }{ Volume{4:9}; Delete; }
