// A CAD part for the 3D constrained benchmarks (scripts/bench_constrained3d.py): a unit box
// less a corner sphere and a through hole, with a torus fused on its bottom face. Flat faces
// meshed with long thin triangles, curved ones with small angles near the seams: the surfaces
// `gmsh -2` makes from CAD. Its triangle count follows -clmax (0.05: 6.6k, 0.015: 71k,
// 0.005: 624k triangles with Gmsh 4.8).
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Sphere(2) = {1, 1, 1, 0.5};
BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Cylinder(3) = {0.25, 0.25, -0.1, 0, 0, 1.2, 0.12};
BooleanDifference{ Volume{1}; Delete; }{ Volume{3}; Delete; }
Torus(4) = {0.5, 0.5, 0, 0.3, 0.08};
BooleanUnion{ Volume{1}; Delete; }{ Volume{4}; Delete; }
