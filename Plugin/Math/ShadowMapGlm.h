// Conversions between VTK's row-major matrices and arrays and GLM's types, for
// the code that hands VTK's camera and lights to the fits (and back).
#ifndef ShadowMapGlm_h
#define ShadowMapGlm_h

#include "vtkMatrix4x4.h"

#include <glm/glm.hpp>

namespace shadowmaps
{
inline glm::dmat4 ToGlm(vtkMatrix4x4* m)
{
  glm::dmat4 result;
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      result[column][row] = m->GetElement(row, column);
    }
  }
  return result;
}

inline glm::dvec3 ToGlm(const double v[3])
{
  return { v[0], v[1], v[2] };
}

inline void ToVtk(const glm::dmat4& m, vtkMatrix4x4* result)
{
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      result->SetElement(row, column, m[column][row]);
    }
  }
}
} // namespace shadowmaps

#endif
