// An open-topped box with walls 0.02 thick and a cylindrical boss inside (issue 20): thin walls
// put the two sides' triangles close together.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 0.8, 0.5};
Box(2) = {0.02, 0.02, 0.02, 0.96, 0.76, 0.6};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Cylinder(3) = {0.5, 0.4, 0, 0, 0, 0.3, 0.1};
BooleanUnion{ Volume{1}; Delete; }{ Volume{3}; Delete; }
Cylinder(4) = {0.5, 0.4, -0.1, 0, 0, 0.5, 0.04};
BooleanDifference{ Volume{1}; Delete; }{ Volume{4}; Delete; }
