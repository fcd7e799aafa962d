# The module's sources compiled against a VTK that was configured but not built
# (scripts/vtk97.sh makes one of VTK 9.7; docs/VTK97.md): `cmake -P
# CompileModule.cmake` with SOURCE_DIR (this project), VTK_DIR (that VTK's build
# tree) and OUT (a folder of its own) configures the module alone against it,
# then compiles each of its sources with -fsyntax-only (scripts/syntax_only.sh)
# and fails on any error. Nothing links: the VTK has no libraries.
include("${CMAKE_CURRENT_LIST_DIR}/../RunOrFail.cmake")

# -Wno-dev: VTK's vtk_module_add_module warns about every header in a folder of
# Plugin/ (9.6 already did).
run_or_fail("configure" "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${OUT}" -G Ninja -Wno-dev
  "-DVTK_DIR=${VTK_DIR}" -DSHADOWMAPS_WRAP_PYTHON=OFF -DSHADOWMAPS_BUILD_TOOLS=OFF
  -DSHADOWMAPS_BUILD_TESTING=OFF
  "-DCMAKE_CXX_COMPILER_LAUNCHER=${SOURCE_DIR}/scripts/syntax_only.sh")

# The module's object files, by the names Ninja gives them: building its
# library would link.
execute_process(COMMAND ninja -C "${OUT}" -t targets all
  OUTPUT_VARIABLE targets RESULT_VARIABLE result)
string(REGEX MATCHALL "[^\n:]*RenderingShadowMaps\\.dir/[^\n:]*\\.o" objects "${targets}")
list(LENGTH objects count)
if (NOT result EQUAL 0 OR count EQUAL 0)
  message(FATAL_ERROR "No object files of the module in ${OUT}.")
endif ()
message(STATUS "Compiling ${count} sources of the module against ${VTK_DIR}")
run_or_fail("compile" "${CMAKE_COMMAND}" --build "${OUT}" --target ${objects} -- -k 0)
