# CTest tests of `dtlab mesh` for volumes on real surfaces (issue 17, "Done when"): a handful of the
# closed surfaces of Debian's CGAL data (libcgal-demo: /usr/share/doc/libcgal-dev/data.tar.gz),
# each a few seconds, meshed in the classical case and with a --size, each passing --verify; and
# surfaces of the same data that are not closed volumes (open, degenerate faces, duplicate vertices,
# polygons that are not planar, a malformed file, a surface that intersects itself) refused by name with exit 1 and no output. Each case runs
# cli/mesh3d_cgal_check.cmake in a scratch directory; skipped (exit 77) when the archive is absent.
# The outcome on every surface of the archive is in docs/performance_mesh3d.md.
if(NOT TARGET dtlab_cli)
  return()
endif()

set(_dtlab_cgal_archive /usr/share/doc/libcgal-dev/data.tar.gz)
# <kind>:<file>[:<size>] (sizes about 1/15 of the bounding box's diagonal), then for refusals the
# stderr regex.
set(_dtlab_cgal_cases
    "mesh:eight.off" "mesh:eight.off:0.0754"          # genus 2
    "mesh:sphere.stl" "mesh:sphere.stl:0.115"          # STL
    "mesh:cactus.off" "mesh:cactus.off:0.0979"
    "mesh:blob-closed.off" "mesh:blob-closed.off:0.209"
    "mesh:helmet.off" "mesh:helmet.off:0.0928"
    "mesh:cube_quad.off:0.231"                          # quadrilateral faces
    "mesh:tripod.off" "mesh:tripod.off:0.0909"
    "refuse:open_cube.off" "refuse:degtri_sliding.off" "refuse:oblong-shuffled.off" "refuse:torus_quad.off"
    "refuse:prim.off" "refuse:elk.off"
    "mesh_nonplanar:torus_quad.off" "mesh_nonplanar:double-torus-example.off")  # quads off their plane
set(_dtlab_cgal_expect_open_cube.off "the surface is open: 4 free edge")
set(_dtlab_cgal_expect_degtri_sliding.off "degenerate face")
set(_dtlab_cgal_expect_oblong-shuffled.off "duplicate vertex pair")
set(_dtlab_cgal_expect_torus_quad.off "face 0 is not planar")
set(_dtlab_cgal_expect_prim.off "more lines than the header's 7 faces")
set(_dtlab_cgal_expect_elk.off "the surface intersects itself: 7 pair")

foreach(_dtlab_case ${_dtlab_cgal_cases})
  string(REPLACE ":" ";" _dtlab_parts "${_dtlab_case}")
  list(GET _dtlab_parts 1 _dtlab_file)
  string(REPLACE ":" "_" _dtlab_name "${_dtlab_case}")
  string(REPLACE "." "_" _dtlab_name "${_dtlab_name}")
  add_test(NAME cli_mesh3d_cgal_${_dtlab_name}
           COMMAND /bin/sh -c "[ -f \"$1\" ] || exit 77; shift; exec \"$@\"" sh ${_dtlab_cgal_archive}
                   ${CMAKE_COMMAND} -DDTLAB=$<TARGET_FILE:dtlab_cli> -DARCHIVE=${_dtlab_cgal_archive}
                   -DWORK=${PROJECT_BINARY_DIR}/cli-mesh3d-cgal-test/${_dtlab_name} -DCASE=${_dtlab_case}
                   "-DEXPECT=${_dtlab_cgal_expect_${_dtlab_file}}" -P ${CMAKE_CURRENT_LIST_DIR}/cli/mesh3d_cgal_check.cmake)
  set_tests_properties(cli_mesh3d_cgal_${_dtlab_name} PROPERTIES TIMEOUT 120 SKIP_RETURN_CODE 77)
endforeach()
