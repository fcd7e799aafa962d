# Tests of the measurement code: the exact shadow oracle (Measurement/
# ShadowOracle.cxx, library ShadowMeasure), the metrics and `vtkshadows bench`. Included from Testing/CMakeLists.txt, so relative paths are
# relative to Testing/. The tests render, so they run under xvfb-run.
if (NOT TARGET ShadowMeasure)
  return ()
endif ()
include(GoogleTest)

set(shadoworacle_test_vtk_modules
  VTK::CommonCore
  VTK::CommonDataModel
  VTK::FiltersSources
  VTK::RenderingCore
  VTK::RenderingOpenGL2
  VTK::RenderingVolumeOpenGL2)

add_executable(TestShadowOracle Cxx/TestShadowOracle.cxx)
target_link_libraries(TestShadowOracle PRIVATE
  ShadowMeasure
  ShadowMaps::RenderingShadowMaps   # vtkAbstractShadowMapPass::CASTS_SHADOWS()
  ${shadoworacle_test_vtk_modules}
  glm::glm
  GTest::gtest_main)
vtk_module_autoinit(TARGETS TestShadowOracle MODULES ${shadoworacle_test_vtk_modules})
gtest_discover_tests(TestShadowOracle DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300)

add_executable(TestShadowMetrics Cxx/TestShadowMetrics.cxx)
target_link_libraries(TestShadowMetrics PRIVATE ShadowMetrics GTest::gtest_main)
gtest_discover_tests(TestShadowMetrics)

# The robustness sweep: its draws, its regression cases and a fixed-seed sweep.
add_executable(TestShadowSweep Cxx/TestShadowSweep.cxx)
target_link_libraries(TestShadowSweep PRIVATE ShadowBench glm::glm GTest::gtest_main)
target_compile_definitions(TestShadowSweep PRIVATE
  SHADOWMAPS_TEST_OUTPUT_DIR="${CMAKE_CURRENT_BINARY_DIR}/Output")
vtk_module_autoinit(TARGETS TestShadowSweep MODULES ${shadowbench_vtk_modules}
  ${shadowscenes_vtk_modules} ${shadowtechniques_vtk_modules} ShadowMaps::RenderingShadowMaps)
gtest_discover_tests(TestShadowSweep DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 900)

# What a steady frame asks of the GL per prop (Measurement/ShadowGLCalls.h).
add_executable(TestShadowGLCalls Cxx/TestShadowGLCalls.cxx)
target_link_libraries(TestShadowGLCalls PRIVATE ShadowBench GTest::gtest_main)
vtk_module_autoinit(TARGETS TestShadowGLCalls MODULES ${shadowbench_vtk_modules}
  ${shadowscenes_vtk_modules} ${shadowtechniques_vtk_modules} ShadowMaps::RenderingShadowMaps)
gtest_discover_tests(TestShadowGLCalls DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300)

if (TARGET vtkshadows)
  add_test(NAME CLI.BenchAndAnalyze
    COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_bench.py"
            "$<TARGET_FILE:vtkshadows>" "${CMAKE_CURRENT_BINARY_DIR}/Output")
  set_tests_properties(CLI.BenchAndAnalyze PROPERTIES TIMEOUT 900)
  add_test(NAME CLI.Sweep
    COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_sweep.py"
            "$<TARGET_FILE:vtkshadows>" "${CMAKE_CURRENT_BINARY_DIR}/Output")
  set_tests_properties(CLI.Sweep PROPERTIES TIMEOUT 900)
endif ()
# The script that reads the automatic pass's rules off a sweep (docs/AUTOMATIC.md).
add_test(NAME Measurement.AutomaticRules
  COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_SOURCE_DIR}/Python/test_automatic_rules.py"
          "${PROJECT_SOURCE_DIR}/Measurement/automatic_rules.py" "${CMAKE_CURRENT_BINARY_DIR}/Output")

# A user's model the right way up, and what `vtkshadows analyze` recommends.
add_executable(TestShadowModelUp Cxx/TestShadowModelUp.cxx)
target_link_libraries(TestShadowModelUp PRIVATE ShadowScenes VTK::IOPLY VTK::FiltersGeneral
  VTK::FiltersCore VTK::FiltersSources VTK::RenderingCore VTK::RenderingOpenGL2 GTest::gtest_main)
vtk_module_autoinit(TARGETS TestShadowModelUp MODULES ${shadowscenes_vtk_modules})
gtest_discover_tests(TestShadowModelUp DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300)

# The benchmark's time-varying scene: new geometry every step.
add_executable(TestShadowScenes Cxx/TestShadowScenes.cxx)
target_link_libraries(TestShadowScenes PRIVATE ShadowScenes VTK::RenderingCore GTest::gtest_main)
vtk_module_autoinit(TARGETS TestShadowScenes MODULES ${shadowscenes_vtk_modules})
gtest_discover_tests(TestShadowScenes DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300)

add_executable(TestShadowRecommendation Cxx/TestShadowRecommendation.cxx)
target_link_libraries(TestShadowRecommendation PRIVATE ShadowBench GTest::gtest_main)
gtest_discover_tests(TestShadowRecommendation)
