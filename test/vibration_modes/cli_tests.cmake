# Runs of `tvf modes` (included by test/tangent_vector_fields/tool/CMakeLists.txt, which defines
# tvf_cli_test and the meshes; CGAL's sphere, 162 vertices).

# Vibration modes (Chapter 5): ordinary shell modes with their completeness proof, the scalar
# problem, compressed modes with their table, and the .vtp with every mode as a point array.
tvf_cli_test(modes.shell success ARGS modes ${SPHERE} -k 6 -o ${CLI_OUT}/modes.vtp --save ${CLI_OUT}/modes.vmb
             OUTPUTS ${CLI_OUT}/modes.vtp ${CLI_OUT}/modes.vmb SETUP modes_saved
             STDOUT "shell problem, 486 unknowns, kernel 6 \\(rigid motions\\).*6 ordinary modes: .*complete below .*\\| 6 \\| ")
tvf_cli_test(modes.scalar success ARGS modes ${SPHERE} -k 3 --scalar
             STDOUT "scalar \\(cotangent Laplacian\\) problem, 162 unknowns, kernel 1 \\(constants\\).*\\| 3 \\| ")
tvf_cli_test(modes.compressed success ARGS modes ${SPHERE} -k 2 --compressed --mu-scale 8 -o ${CLI_OUT}/compressed_modes.vtp
             OUTPUTS ${CLI_OUT}/compressed_modes.vtp
             STDOUT "2 compressed modes, mu [0-9.e+-]+: .*\\| 2 \\| [0-9.e+-]+ \\| [0-9.e+-]+ \\| [0-9.]+ % \\|")
tvf_cli_test(modes.pinned success ARGS modes ${SPHERE} -k 2 --pin 0,1,2
             STDOUT "kernel 0 \\(rigid motions\\)")
tvf_cli_test(modes.bad_pin usage ARGS modes ${SPHERE} --pin 0,x STDERR "'--pin': 'x' is not a vertex index")
tvf_cli_test(modes.pin_outside usage ARGS modes ${SPHERE} --pin 7,100000 STDERR "'--pin': vertex 100000 is not in the mesh \\(162 vertices\\)")
tvf_cli_test(modes.negative_mu usage ARGS modes ${SPHERE} --compressed --mu -1 STDERR "mu must be finite and >= 0")
tvf_cli_test(modes.too_many failure ARGS modes ${SPHERE} -k 1000 --scalar STDERR "error: .*1000")
tvf_cli_test(modes.load success ARGS modes ${SPHERE} --load ${CLI_OUT}/modes.vmb -o ${CLI_OUT}/modes_loaded.vtp
             OUTPUTS ${CLI_OUT}/modes_loaded.vtp STDOUT "loaded 6 ordinary modes" REQUIRES modes_saved)
tvf_cli_test(modes.load_other_pins failure ARGS modes ${SPHERE} --load ${CLI_OUT}/modes.vmb --pin 3
             STDERR "computed with other pinned vertices" REQUIRES modes_saved)
tvf_cli_test(modes.load_other_mesh failure ARGS modes ${ELEPHANT} --load ${CLI_OUT}/modes.vmb
             STDERR "other connectivity" REQUIRES modes_saved)
if(TVF_HAS_CAIRO)
  tvf_cli_test(modes.pictures success ARGS modes ${SPHERE} -k 2 --pictures ${CLI_OUT}/shell_mode
               OUTPUTS ${CLI_OUT}/shell_mode_01.png ${CLI_OUT}/shell_mode_02.png STDOUT "wrote 2 pictures")
  tvf_cli_test(modes.scalar_pictures success ARGS modes ${SPHERE} -k 1 --scalar --pictures ${CLI_OUT}/scalar_mode
               OUTPUTS ${CLI_OUT}/scalar_mode_01.png)
endif()
tvf_cli_test(modes.l1_budget success ARGS modes ${SPHERE} -k 2 --compressed --l1-budget 0.5
             STDOUT "2 compressed modes, L1 budget [0-9.e+-]+: ")
tvf_cli_test(modes.zero_budget usage ARGS modes ${SPHERE} --compressed --l1-budget 0 STDERR "'--l1-budget' must be finite and > 0")
