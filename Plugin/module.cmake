# Declares ShadowMaps::RenderingShadowMaps (included from the root CMakeLists.txt
# when vtk_module_build() visits the module directory).
set(shadowmaps_shaders
  vtkShadowMapsCasterFS
  vtkShadowMapsDepthLookupFS
  vtkShadowMapsLinearDepthFS
  vtkShadowMapsReceiverFS
  vtkShadowMapsViewFS)
set(shadowmaps_shader_sources)
set(shadowmaps_shader_headers)
foreach (shader IN LISTS shadowmaps_shaders)
  vtk_encode_string(
    INPUT         "${CMAKE_CURRENT_LIST_DIR}/../Shaders/${shader}.glsl"
    NAME          "${shader}"
    HEADER_OUTPUT header
    SOURCE_OUTPUT source)
  list(APPEND shadowmaps_shader_sources "${source}")
  list(APPEND shadowmaps_shader_headers "${header}")
endforeach ()

vtk_module_add_module(ShadowMaps::RenderingShadowMaps
  CLASSES
    Plugin/vtkAbstractShadowMapPass
    Plugin/vtkCascadedShadowMapPass
    Plugin/vtkWarpedShadowMapPass
  PRIVATE_CLASSES
    Plugin/vtkShadowMapCasterPass
  SOURCES
    Plugin/ShadowMapCascades.cxx
    Plugin/ShadowMapFocusing.cxx
    Plugin/ShadowMapPerspective.cxx
    Plugin/ShadowMapTextureArray.cxx
    Plugin/ShadowMapTrapezoid.cxx
    Plugin/ShadowMapWarping.cxx
    ${shadowmaps_shader_sources}
  PRIVATE_HEADERS
    Plugin/ShadowMapCascades.h
    Plugin/ShadowMapFocusing.h
    Plugin/ShadowMapPerspective.h
    Plugin/ShadowMapTextureArray.h
    Plugin/ShadowMapTrapezoid.h
    Plugin/ShadowMapWarping.h
    Plugin/vtkShadowMapInternals.h
    ${shadowmaps_shader_headers})
vtk_module_include(ShadowMaps::RenderingShadowMaps
  PUBLIC "$<BUILD_INTERFACE:${CMAKE_CURRENT_LIST_DIR}>"
  PRIVATE "$<BUILD_INTERFACE:${CMAKE_CURRENT_BINARY_DIR}>")
vtk_module_link(ShadowMaps::RenderingShadowMaps PRIVATE glm::glm)
