# Runs of `tvf simulate` (included by test/tangent_vector_fields/tool/CMakeLists.txt, which defines
# tvf_cli_test and CLI_OUT).  The body: a 4 x 1 x 1 box of 8 x 2 x 2 cubes, six tetrahedra each
# (written here as a Medit file); vertex (i, j, k) at (i / 2, j / 2, k / 2) is number
# 9 i + 3 j + k + 1.  Each scene's last frame is then read back by check_frame.cmake, which knows
# nothing of the simulator: the drop rests on its floor (z = -0.25, a quarter of the height below
# the box), the cantilever's pinned end (x = 0, vertices 1-9) keeps its rest positions exactly and
# the rest sags.

set(box "MeshVersionFormatted 1\nDimension 3\nVertices\n81\n")
foreach(i RANGE 0 8)
  foreach(j RANGE 0 2)
    foreach(k RANGE 0 2)
      math(EXPR x "5 * ${i}")
      math(EXPR y "5 * ${j}")
      math(EXPR z "5 * ${k}")
      string(APPEND box "${x}e-1 ${y}e-1 ${z}e-1 0\n")
    endforeach()
  endforeach()
endforeach()
string(APPEND box "Tetrahedra\n192\n")
foreach(i RANGE 0 7)
  foreach(j RANGE 0 1)
    foreach(k RANGE 0 1)
      # The cube's corners (1-based), and its six tetrahedra from corner 000 to corner 111.
      foreach(c 000 100 010 001 110 101 011 111)
        string(SUBSTRING ${c} 0 1 a)
        string(SUBSTRING ${c} 1 1 b)
        string(SUBSTRING ${c} 2 1 d)
        math(EXPR v${c} "9 * (${i} + ${a}) + 3 * (${j} + ${b}) + ${k} + ${d} + 1")
      endforeach()
      foreach(path "100 110" "100 101" "010 110" "010 011" "001 101" "001 011")
        string(REPLACE " " ";" corners "${path}")
        list(GET corners 0 p)
        list(GET corners 1 q)
        string(APPEND box "${v000} ${v${p}} ${v${q}} ${v111} 0\n")
      endforeach()
    endforeach()
  endforeach()
endforeach()
string(APPEND box "End\n")
file(WRITE ${CLI_OUT}/box.mesh "${box}")
file(WRITE ${CLI_OUT}/broken_box.mesh "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n")

function(pd_frame_check name fixture file)
  add_test(NAME cli.simulate.${name}.frame
           COMMAND ${CMAKE_COMMAND} -DFILE=${file} ${ARGN} -P ${PROJECT_SOURCE_DIR}/test/support/check_frame.cmake)
  set_tests_properties(cli.simulate.${name}.frame PROPERTIES FIXTURES_REQUIRED ${fixture} LABELS cli)
endfunction()

tvf_cli_test(simulate.drop success
             ARGS simulate ${CLI_OUT}/box.mesh --scene drop --frames 45 -o ${CLI_OUT}/drop
             OUTPUTS ${CLI_OUT}/drop/frame_0045.obj
             STDOUT "a solid, 81 vertices, 192 tetrahedra.*floor at z = -0.25"
             SETUP simulate_drop)
pd_frame_check(drop simulate_drop ${CLI_OUT}/drop/frame_0045.obj -DMIN_Z_AT_LEAST=-0.2500001 -DMIN_Z_AT_MOST=-0.249)
# Reduced: the floor holds every drawn vertex (the box's boundary), not only the samples and the
# 30 sampled elements' vertices (with those alone the lowest vertex ends at -0.251).
tvf_cli_test(simulate.drop_reduced success
             ARGS simulate ${CLI_OUT}/box.mesh --scene drop --frames 45 --reduced --projection-columns 10
                  --sampled-elements 30 -o ${CLI_OUT}/drop_reduced
             OUTPUTS ${CLI_OUT}/drop_reduced/frame_0045.obj
             STDOUT "hyper-reduced PD.*floor at z = -0.25"
             SETUP simulate_drop_reduced)
pd_frame_check(drop_reduced simulate_drop_reduced ${CLI_OUT}/drop_reduced/frame_0045.obj -DMIN_Z_AT_LEAST=-0.25 -DMIN_Z_AT_MOST=-0.249)
tvf_cli_test(simulate.cantilever success
             ARGS simulate ${CLI_OUT}/box.mesh --scene cantilever --frames 30 -o ${CLI_OUT}/cantilever
             OUTPUTS ${CLI_OUT}/cantilever/frame_0030.obj
             STDOUT "pinned vertices: 9, largest distance from their rest positions 0\n"
             SETUP simulate_cantilever)
pd_frame_check(cantilever simulate_cantilever ${CLI_OUT}/cantilever/frame_0030.obj -DMIN_Z_AT_MOST=-0.01
               "-DVERTICES=1:0:0:0\;2:0:0:0.5\;3:0:0:1\;4:0:0.5:0\;5:0:0.5:0.5\;6:0:0.5:1\;7:0:1:0\;8:0:1:0.5\;9:0:1:1")
tvf_cli_test(simulate.grab_reduced_vtp success
             ARGS simulate ${CLI_OUT}/box.mesh --scene grab --frames 10 --reduced --format vtp -o ${CLI_OUT}/grab
             OUTPUTS ${CLI_OUT}/grab/frame_0010.vtp ${CLI_OUT}/grab/frames.pvd
             STDOUT "hyper-reduced PD: 5 position samples \\(k = 20\\).*grabbed vertices: 9 lifted by 1.2")
tvf_cli_test(simulate.shell success ARGS simulate ${SPHERE} --scene drop --frames 3 --bending 1
             STDOUT "a shell, 162 vertices, 320 triangles, 2 element groups")
tvf_cli_test(simulate.unknown_scene usage ARGS simulate ${CLI_OUT}/box.mesh --scene fall
             STDERR "'--scene' must be drop, cantilever or grab, not 'fall'")
tvf_cli_test(simulate.no_frames usage ARGS simulate ${CLI_OUT}/box.mesh --frames 0
             STDERR "'--frames' must be at least 1")
tvf_cli_test(simulate.truncated_mesh failure ARGS simulate ${CLI_OUT}/broken_box.mesh
             STDERR "broken_box.mesh': .*line")

# The hyper-reduced precomputation saved, then loaded by a second run: the same frames, byte for
# byte; loaded with other reduction options: refused with the reason.
tvf_cli_test(simulate.reduced_save success
             ARGS simulate ${CLI_OUT}/box.mesh --scene cantilever --frames 5 --reduced --save ${CLI_OUT}/box.pdr
                  -o ${CLI_OUT}/reduced_saved
             OUTPUTS ${CLI_OUT}/box.pdr ${CLI_OUT}/reduced_saved/frame_0005.obj
             STDOUT "precomputation [0-9.]+ s\nsaved the precomputation to"
             SETUP simulate_reduced_saved)
tvf_cli_test(simulate.reduced_load success
             ARGS simulate ${CLI_OUT}/box.mesh --scene cantilever --frames 5 --reduced --load ${CLI_OUT}/box.pdr
                  -o ${CLI_OUT}/reduced_loaded
             OUTPUTS ${CLI_OUT}/reduced_loaded/frame_0005.obj
             STDOUT "loaded in [0-9.]+ s"
             SETUP simulate_reduced_loaded REQUIRES simulate_reduced_saved)
add_test(NAME cli.simulate.reduced_load.same_frames
         COMMAND ${CMAKE_COMMAND} -E compare_files ${CLI_OUT}/reduced_saved/frame_0005.obj
                 ${CLI_OUT}/reduced_loaded/frame_0005.obj)
set_tests_properties(cli.simulate.reduced_load.same_frames PROPERTIES FIXTURES_REQUIRED simulate_reduced_loaded LABELS cli)
tvf_cli_test(simulate.reduced_load_other_options failure
             ARGS simulate ${CLI_OUT}/box.mesh --reduced --samples 4 --load ${CLI_OUT}/box.pdr
             STDERR "made with other reduction options: number_of_samples 5 in the file, 4 given"
             REQUIRES simulate_reduced_saved)
tvf_cli_test(simulate.save_needs_reduced usage ARGS simulate ${CLI_OUT}/box.mesh --save ${CLI_OUT}/full.pdr
             STDERR "give '--reduced'")

# A closed surface filled with tetrahedra (Mesh_3): the frames show the surface's own 162
# vertices, and the solid falls onto the floor (at z = -0.7447, a quarter of the height below the
# sphere): its lowest vertex rests there; an open surface is refused with the reason.
tvf_cli_test(simulate.solid_from_surface success
             ARGS simulate ${SPHERE} --solid --cell-size 0.15 --frames 40 -o ${CLI_OUT}/sphere_solid
                  --tetrahedra ${CLI_OUT}/sphere_solid.mesh
             OUTPUTS ${CLI_OUT}/sphere_solid/frame_0040.obj ${CLI_OUT}/sphere_solid.mesh
             STDOUT "tetrahedra: [0-9]+ vertices, [0-9]+ tetrahedra \\(Mesh_3.*a solid"
             SETUP simulate_sphere_solid)
pd_frame_check(solid_from_surface simulate_sphere_solid ${CLI_OUT}/sphere_solid/frame_0040.obj -DVERTEX_COUNT=162
               -DMIN_Z_AT_LEAST=-0.76 -DMIN_Z_AT_MOST=-0.7)
file(WRITE ${CLI_OUT}/one_triangle.off "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
tvf_cli_test(simulate.solid_from_open_surface failure ARGS simulate ${CLI_OUT}/one_triangle.off --solid
             STDERR "one_triangle.off': tetrahedralize: the surface is open \\(3 border edges\\)")
