# ShadowMeasure: the exact shadow oracle (ShadowOracle.cxx, Embree 3) that
# the benchmarks and tests measure shadow maps against. Included at the end of
# Examples/CMakeLists.txt.
find_package(Threads REQUIRED)

set(shadowmeasure_vtk_modules
  VTK::CommonCore
  VTK::CommonDataModel
  VTK::CommonExecutionModel
  VTK::CommonMath
  VTK::FiltersCore        # vtkGlyph3D
  VTK::RenderingCore      # actors, mappers, vtkGlyph3DMapper, vtkPointGaussianMapper
  VTK::RenderingOpenGL2)  # vtkCompositePolyDataMapper2

add_library(ShadowMeasure STATIC ShadowOracle.cxx ShadowOracleVolumes.cxx ShadowAreaLight.cxx)
target_include_directories(ShadowMeasure PUBLIC "${CMAKE_CURRENT_SOURCE_DIR}")
target_link_libraries(ShadowMeasure
  PUBLIC
    glm::glm
    ${shadowmeasure_vtk_modules}
  PRIVATE
    embree
    ShadowMaps::RenderingShadowMaps   # CASTS_SHADOWS(), GetLightSize()
    Threads::Threads)
# Benchmarks may link it into shared libraries or Python modules.
set_target_properties(ShadowMeasure PROPERTIES POSITION_INDEPENDENT_CODE ON)
# The library only down-casts mappers and creates no factory-overridden
# objects, so it needs no vtk_module_autoinit; programs that render do.
