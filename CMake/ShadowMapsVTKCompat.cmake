# What differs between the VTK versions the module builds against (9.1 to 9.7)
# at the level of CMake, after find_package(VTK); the C++ side is
# Plugin/Compat/ShadowMapVTKCompat.h.
#
# SHADOWMAPS_VTK_GL_TARGETS: the targets that give a program the OpenGL API
#   (for glGetError and friends outside the module): VTK 9.4 replaced VTK::glew
#   and VTK::opengl with VTK::glad.
if (TARGET VTK::glad)
  set(SHADOWMAPS_VTK_GL_TARGETS VTK::glad)
elseif (TARGET VTK::glew)
  set(SHADOWMAPS_VTK_GL_TARGETS VTK::glew VTK::opengl)
else ()
  message(FATAL_ERROR "VTK ${VTK_VERSION} has neither VTK::glad nor VTK::glew: "
    "this module needs VTK's OpenGL loader (VTK 9.1 to 9.7 have one of them).")
endif ()

# SHADOWMAPS_BASELINE_VARIANT: the folder of Testing/Data/Baseline that holds
#   this VTK version's own baselines, for the frames it shades differently from
#   VTK 9.1 (its lighting code, or its Debian's Mesa, differs); empty on 9.1.
#   A test reads a variant where one exists and 9.1's baseline elsewhere.
if (VTK_VERSION VERSION_LESS 9.2)
  set(SHADOWMAPS_BASELINE_VARIANT "")
else ()
  set(SHADOWMAPS_BASELINE_VARIANT "vtk-${VTK_VERSION_MAJOR}.${VTK_VERSION_MINOR}")
endif ()
