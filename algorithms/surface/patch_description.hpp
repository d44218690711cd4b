// A patch described in JSON (the input of `dtlab mesh PATCH.json --surface-only`): an object with
// "type" and the parameters of that type (lengths in the model's units, angles none):
//   {"type": "plane", "origin": [x,y,z], "e1": [..], "e2": [..], "u": [u0,u1], "v": [v0,v1]}
//   {"type": "sphere", "centre": [..], "radius": r}
//   {"type": "cylinder", "centre": [..], "axis": [..], "radius": r, "height": h}
//   {"type": "cone", "centre": [..], "axis": [..], "radius0": r0, "radius1": r1, "height": h}
//   {"type": "torus", "centre": [..], "axis": [..], "major": R, "minor": r}
//   {"type": "sine_graph", "amplitude": 3, "frequency": [2, 2], "radius": 3}   (the book's sigma, §6.4)
//   {"type": "bspline", "degree": [p,q], "count": [nu,nv], "controls": [[x,y,z], ...] (nu rows of nv),
//    "knots_u": [...], "knots_v": [...]}
// "centre" defaults to the origin, "axis" to z, "sine_graph"'s fields to the book's values.
#pragma once

#include "algorithms/surface/patch_surface3.hpp"
#include "mesh/io/json_value.hpp"

namespace dtlab {

// InputError "unknown patch type 'X' (known: ...)", "patch: unknown key 'K' for a T", a missing
// or mistyped field by name, and the degenerate patches of PatchSurface3 by name.
PatchSurface3 patch_from_description(const JsonValue& description);

}  // namespace dtlab
