// An L-shaped bracket with rounded edges and two bolt holes (issue 20): fillets make thin
// curved strips between flat faces.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 0.6, 0.15};
Box(2) = {0, 0, 0, 0.15, 0.6, 0.8};
BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Cylinder(3) = {0.6, 0.3, -0.1, 0, 0, 0.4, 0.1};
Cylinder(4) = {-0.1, 0.3, 0.5, 0.4, 0, 0, 0.1};
BooleanDifference{ Volume{1}; Delete; }{ Volume{3, 4}; Delete; }
Fillet{1}{Curve{:}}{0.03}
