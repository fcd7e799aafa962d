# Unit tests of the focusing and warping math (Plugin/Math/ShadowMap*.cxx). Included from
# Testing/CMakeLists.txt, so relative paths are relative to Testing/. The math
# source is compiled into the test directly: the test needs GLM and GoogleTest
# only, not the VTK module.
find_package(GTest REQUIRED)
find_package(glm REQUIRED)

add_executable(TestShadowMapFocusing
  Cxx/TestShadowMapFocusing.cxx
  Cxx/TestShadowMapWarping.cxx
  Cxx/TestShadowMapTrapezoid.cxx
  Cxx/TestShadowMapPerspective.cxx
  Cxx/TestShadowMapCascades.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapFocusing.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapWarping.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapTrapezoid.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapPerspective.cxx
  ${PROJECT_SOURCE_DIR}/Plugin/Math/ShadowMapCascades.cxx)
target_include_directories(TestShadowMapFocusing PRIVATE ${PROJECT_SOURCE_DIR}/Plugin/Math)
target_compile_features(TestShadowMapFocusing PRIVATE cxx_std_17)
target_link_libraries(TestShadowMapFocusing PRIVATE glm::glm GTest::gtest_main)

include(GoogleTest)
gtest_discover_tests(TestShadowMapFocusing)
