// What differs between the VTK versions the module builds against (9.1 to 9.7)
// at the level of C++ headers, so that no other file names a VTK version; the
// CMake side is CMake/ShadowMapsVTKCompat.cmake.
//
// - The OpenGL loader: VTK 9.4 replaced GLEW (vtk_glew.h, VTK::glew) with glad
//   (vtk_glad.h, VTK::glad). Both declare the GL core API the module calls.
// - The composite polydata mapper (used by the oracle and the tests, not the
//   module): VTK 9.3 rewrote vtkCompositePolyDataMapper (RenderingCore) to do
//   what vtkCompositePolyDataMapper2 (RenderingOpenGL2) did, deprecated the
//   latter and 9.5 removed it. vtkShadowCompositeMapper names whichever draws
//   composite data with per-block display attributes.
// - Uniforms (docs/VTK97.md): VTK 9.7's vtkShaderProgram keeps the value each
//   SetUniform* last sent to a program and skips the GL call that would send it
//   again. The module sets every uniform through SetUniform*, so nothing needs
//   a change; vtkShadowSkipsRepeatedUniforms tells the GL call counts of the
//   tests and benchmarks that a value set again may cost no call.
// - Cell arrays: VTK 9.6 may hold cells as fixed-size cells (affine offsets)
//   or generic arrays besides the plain 32- and 64-bit arrays
//   (ShadowMapClosedSurfaces reads the plain ones directly, the others through
//   the cell iterator); VTK_SHADOW_FIXED_SIZE_CELL_ARRAYS says the tests can
//   make them.
#ifndef ShadowMapVTKCompat_h
#define ShadowMapVTKCompat_h

#include "vtkVersionMacros.h"

#if __has_include("vtk_glad.h")
#include "vtk_glad.h" // IWYU pragma: export
#else
#include "vtk_glew.h" // IWYU pragma: export
#endif

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
#include "vtkCompositePolyDataMapper.h" // IWYU pragma: export
using vtkShadowCompositeMapper = vtkCompositePolyDataMapper;
#else
#include "vtkCompositePolyDataMapper2.h" // IWYU pragma: export
using vtkShadowCompositeMapper = vtkCompositePolyDataMapper2;
#endif

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 6, 0)
#define VTK_SHADOW_FIXED_SIZE_CELL_ARRAYS 1
#else
#define VTK_SHADOW_FIXED_SIZE_CELL_ARRAYS 0
#endif

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 7, 0)
constexpr bool vtkShadowSkipsRepeatedUniforms = true;
#else
constexpr bool vtkShadowSkipsRepeatedUniforms = false;
#endif

#endif
