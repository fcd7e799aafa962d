# Declares ShadowMaps::RenderingShadowMaps (included from the root CMakeLists.txt
# when vtk_module_build() visits the module directory). The folders of Plugin/
# are its layers: Compat (what differs between VTK versions), Math (pure
# functions of the fits), Scene (what the passes read of the casters' data),
# Views and Representations (the two strategies of a pass), Choice (what the
# automatic pass chooses them from), OpenGL (GL objects
# and the shader code injected into mappers) and Passes (the vtkRenderPass
# subclasses that coordinate them).
set(shadowmaps_shaders
  vtkShadowMapsAnalysisFS
  vtkShadowMapsBlurFS
  vtkShadowMapsCasterFS
  vtkShadowMapsImpostorDepthFS
  vtkShadowMapsImpostorSizes
  vtkShadowMapsSpriteFS
  vtkShadowMapsSpriteVS
  vtkShadowMapsTubeFS
  vtkShadowMapsTubeGS
  vtkShadowMapsDepthLookupFS
  vtkShadowMapsDualDepthLookupFS
  vtkShadowMapsFilterFS
  vtkShadowMapsLinearDepthFS
  vtkShadowMapsLinearDepthResolveFS
  vtkShadowMapsLightDepthFS
  vtkShadowMapsMomentsFS
  vtkShadowMapsReceiverFS
  vtkShadowMapsSoftFS
  vtkShadowMapsSoftKernelFS
  vtkShadowMapsSoftMomentsFS
  vtkShadowMapsTransmittanceFS
  vtkShadowMapsTransmittedFS
  vtkShadowMapsVarianceLookupFS
  vtkShadowMapsViewFS
  vtkShadowMapsVolumeCastingFS
  vtkShadowMapsVolumeCastingVS)
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

set(shadowmaps_folders Choice Compat Math OpenGL Passes Representations Scene Views)

vtk_module_add_module(ShadowMaps::RenderingShadowMaps
  CLASSES
    Plugin/Passes/vtkAbstractShadowMapPass
    Plugin/Passes/vtkAutomaticShadowMapPass
    Plugin/Passes/vtkCascadedShadowMapPass
    Plugin/Passes/vtkDepthShadowMapPass
    Plugin/Passes/vtkDualDepthShadowMapPass
    Plugin/Passes/vtkVarianceShadowMapPass
    Plugin/Passes/vtkShadowMapExchange
    Plugin/Passes/vtkWarpedShadowMapPass
    Plugin/Representations/vtkDepthShadowMapRepresentation
    Plugin/Representations/vtkDualDepthShadowMapRepresentation
    Plugin/Representations/vtkShadowMapRepresentation
    Plugin/Representations/vtkVarianceShadowMapRepresentation
    Plugin/Views/vtkCascadedShadowMapViews
    Plugin/Views/vtkShadowMapViews
    Plugin/Views/vtkUniformShadowMapViews
    Plugin/Views/vtkWarpedShadowMapViews
  HEADERS
    # The setter macro of the classes above, for downstream subclasses too.
    Plugin/vtkShadowMapSetMacros.h
  SOURCES
    Plugin/Choice/ShadowMapLightChoices.cxx
    Plugin/Choice/ShadowMapLightSituation.cxx
    Plugin/Choice/ShadowMapViewsRules.cxx
    Plugin/Math/ShadowMapCascades.cxx
    Plugin/Math/ShadowMapCasterReach.cxx
    Plugin/Math/ShadowMapCrop.cxx
    Plugin/Math/ShadowMapFocusing.cxx
    Plugin/Math/ShadowMapKeptViews.cxx
    Plugin/Math/ShadowMapLightDepth.cxx
    Plugin/Math/ShadowMapPerspective.cxx
    Plugin/Math/ShadowMapPerspectiveCube.cxx
    Plugin/Math/ShadowMapTrapezoid.cxx
    Plugin/Math/ShadowMapWarping.cxx
    Plugin/OpenGL/ShadowMapAnalysis.cxx
    Plugin/OpenGL/ShadowMapBlur.cxx
    Plugin/OpenGL/ShadowMapCasterShader.cxx
    Plugin/OpenGL/ShadowMapCasting.cxx
    Plugin/OpenGL/ShadowMapImpostors.cxx
    Plugin/OpenGL/ShadowMapLinearDepthResolve.cxx
    Plugin/OpenGL/ShadowMapStoreFromLightDepths.cxx
    Plugin/OpenGL/ShadowMapReceiverShader.cxx
    Plugin/OpenGL/ShadowMapRotationNoise.cxx
    Plugin/OpenGL/ShadowMapShaderGroup.cxx
    Plugin/OpenGL/ShadowMapTransmittance.cxx
    Plugin/OpenGL/ShadowMapVolumeCasting.cxx
    Plugin/OpenGL/ShadowMapTextureArray.cxx
    Plugin/Passes/ShadowMapCombination.cxx
    Plugin/Passes/ShadowMapFramePolicy.cxx
    Plugin/Passes/ShadowMapFrameUpdate.cxx
    Plugin/Passes/ShadowMapBuiltCode.cxx
    Plugin/Passes/ShadowMapGroups.cxx
    Plugin/Passes/ShadowMapLayerContent.cxx
    Plugin/Passes/ShadowMapLayerDrawing.cxx
    Plugin/Passes/ShadowMapPassShaders.cxx
    Plugin/Passes/ShadowMapProgramUniforms.cxx
    Plugin/Passes/ShadowMapPropJoining.cxx
    Plugin/Passes/ShadowMapReceiverTextures.cxx
    Plugin/Passes/ShadowMapRendererMaps.cxx
    Plugin/Passes/ShadowMapRendererUse.cxx
    Plugin/Passes/ShadowMapStorageChoice.cxx
    Plugin/Passes/ShadowMapUpdates.cxx
    Plugin/Scene/ShadowMapClosedSurfaces.cxx
    Plugin/Scene/ShadowMapCasterVersion.cxx
    Plugin/Scene/ShadowMapPropParts.cxx
    Plugin/Scene/ShadowMapPropRecords.cxx
    Plugin/Scene/ShadowMapPropRoles.cxx
    Plugin/Scene/ShadowMapSceneReading.cxx
    Plugin/Scene/ShadowMapVolumeReading.cxx
    ${shadowmaps_shader_sources}
  NOWRAP_HEADERS
    # What a downstream views or representation class needs: plain C++ and
    # GLM, which the wrappers need not (and are slow to) parse.
    Plugin/Math/ShadowMapFocusing.h
    Plugin/Math/ShadowMapGlm.h
    Plugin/Math/ShadowMapLightDepth.h
    Plugin/OpenGL/ShadowMapTextureArray.h
    Plugin/Views/ShadowMapLight.h
  PRIVATE_HEADERS
    Plugin/Compat/ShadowMapVTKCompat.h
    Plugin/Math/ShadowMapCascades.h
    Plugin/Math/ShadowMapCasterReach.h
    Plugin/Math/ShadowMapCrop.h
    Plugin/Math/ShadowMapKeptViews.h
    Plugin/Math/ShadowMapPerspective.h
    Plugin/Math/ShadowMapPerspectiveCube.h
    Plugin/Math/ShadowMapTrapezoid.h
    Plugin/Math/ShadowMapWarping.h
    Plugin/OpenGL/ShadowMapAnalysis.h
    Plugin/OpenGL/ShadowMapBlur.h
    Plugin/OpenGL/ShadowMapCasterShader.h
    Plugin/OpenGL/ShadowMapCasting.h
    Plugin/OpenGL/ShadowMapFloatUniforms.h
    Plugin/OpenGL/ShadowMapGlslLiteral.h
    Plugin/OpenGL/ShadowMapImpostors.h
    Plugin/OpenGL/ShadowMapLinearDepthResolve.h
    Plugin/OpenGL/ShadowMapStoreFromLightDepths.h
    Plugin/OpenGL/ShadowMapProgramStamps.h
    Plugin/OpenGL/ShadowMapQuad.h
    Plugin/OpenGL/ShadowMapReceiverShader.h
    Plugin/OpenGL/ShadowMapRotationNoise.h
    Plugin/OpenGL/ShadowMapShaderGroup.h
    Plugin/OpenGL/ShadowMapTransmittance.h
    Plugin/Passes/ShadowMapCombination.h
    Plugin/Passes/ShadowMapFrameUpdate.h
    Plugin/Passes/ShadowMapBuiltCode.h
    Plugin/Passes/ShadowMapGroups.h
    Plugin/Passes/ShadowMapLayerContent.h
    Plugin/Passes/ShadowMapLayerDrawing.h
    Plugin/Passes/ShadowMapPassShaders.h
    Plugin/Passes/ShadowMapPerLight.h
    Plugin/Passes/ShadowMapProgramUniforms.h
    Plugin/Passes/ShadowMapPropJoining.h
    Plugin/Passes/ShadowMapReceiverTextures.h
    Plugin/Passes/ShadowMapRendererMaps.h
    Plugin/Passes/ShadowMapRendererUse.h
    Plugin/Passes/ShadowMapStorageChoice.h
    Plugin/Passes/ShadowMapUpdates.h
    Plugin/Scene/ShadowMapClosedSurfaces.h
    Plugin/Scene/ShadowMapCasterVersion.h
    Plugin/Scene/ShadowMapPropParts.h
    Plugin/Scene/ShadowMapPropRecords.h
    Plugin/Scene/ShadowMapPropRoles.h
    Plugin/Scene/ShadowMapSceneReading.h
    ${shadowmaps_shader_headers})
foreach (folder IN LISTS shadowmaps_folders)
  vtk_module_include(ShadowMaps::RenderingShadowMaps
    PUBLIC "$<BUILD_INTERFACE:${CMAKE_CURRENT_LIST_DIR}/${folder}>")
endforeach ()
vtk_module_include(ShadowMaps::RenderingShadowMaps
  PUBLIC "$<BUILD_INTERFACE:${CMAKE_CURRENT_LIST_DIR}>"
  PRIVATE "$<BUILD_INTERFACE:${CMAKE_CURRENT_BINARY_DIR}>")
vtk_module_link(ShadowMaps::RenderingShadowMaps PUBLIC glm::glm)
