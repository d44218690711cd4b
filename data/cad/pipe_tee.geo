// Two tubes joined in a T (issue 20): curved walls 0.05 thick and their intersection curve.
SetFactory("OpenCASCADE");
Cylinder(1) = {-1, 0, 0, 2, 0, 0, 0.3};
Cylinder(2) = {0, 0, 0, 0, 0, 1, 0.2};
BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Cylinder(3) = {-1.1, 0, 0, 2.2, 0, 0, 0.25};
Cylinder(4) = {0, 0, 0, 0, 0, 1.1, 0.15};
BooleanDifference{ Volume{1}; Delete; }{ Volume{3, 4}; Delete; }
