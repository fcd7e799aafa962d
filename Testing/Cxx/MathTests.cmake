# Unit tests of the fitting math (Plugin/Math/ShadowMap*.cxx): bounds, focusing,
# cube faces, tiles, degenerate input, warping, trapezoids, perspective maps and
# their post-perspective cube,
# cascades, caster reach, the light depth, crops and kept views. Included from Testing/CMakeLists.txt, so relative paths are
# relative to Testing/. The math source is compiled into the test directly: the
# test needs GLM and GoogleTest only, not the VTK module.
add_executable(TestShadowMapMath
  Cxx/TestShadowMapBounds.cxx
  Cxx/TestShadowMapFocusing.cxx
  Cxx/TestShadowMapCubeFaces.cxx
  Cxx/TestShadowMapTiles.cxx
  Cxx/TestShadowMapDegenerate.cxx
  Cxx/TestShadowMapWarping.cxx
  Cxx/TestShadowMapTrapezoid.cxx
  Cxx/TestShadowMapPerspective.cxx
  Cxx/TestShadowMapPerspectiveCube.cxx
  Cxx/TestShadowMapCascades.cxx
  Cxx/TestShadowMapCasterReach.cxx
  Cxx/TestShadowMapLightDepth.cxx
  Cxx/TestShadowMapCrop.cxx
  Cxx/TestShadowMapKeptViews.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapFocusing.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapLightDepth.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapWarping.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapTrapezoid.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapPerspective.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapPerspectiveCube.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapCascades.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapCasterReach.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapCrop.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapKeptViews.cxx)
target_include_directories(TestShadowMapMath PRIVATE ${PROJECT_SOURCE_DIR}/Plugin/Math)
target_compile_features(TestShadowMapMath PRIVATE cxx_std_17)
target_link_libraries(TestShadowMapMath PRIVATE glm::glm GTest::gtest_main)

include(GoogleTest)
gtest_discover_tests(TestShadowMapMath)
