/**
 * Setters of the module's VTK classes refuse what is not a finite number.
 *
 * vtkSetClampMacro lets NaN through (every comparison with NaN is false, so
 * NaN is stored) and turns an infinity into a bound; either may then reach a
 * fit or the shaders. vtkSetFiniteClampMacro declares the same setter and
 * range getters, but a value that is not finite leaves the parameter as it
 * was, with a warning naming the parameter and the value; finite values clamp
 * as vtkSetClampMacro clamps them. Hand-written setters check their values
 * with vtkShadowMapsIsFiniteParameter, which the macro uses too.
 */
#ifndef vtkShadowMapSetMacros_h
#define vtkShadowMapSetMacros_h

#include "vtkObject.h"

#include <cmath>
#include <limits>

/**
 * Whether `value`, given for `parameter` of `object`, is a finite number; if
 * not, warns that the value is ignored and the parameter stays `kept` (where
 * the parameter is one number).
 */
inline bool vtkShadowMapsIsFiniteParameter(vtkObject* object, const char* parameter,
  double value, double kept = std::numeric_limits<double>::quiet_NaN())
{
  if (std::isfinite(value))
  {
    return true;
  }
  if (std::isnan(kept))
  {
    vtkWarningWithObjectMacro(
      object, << parameter << " " << value << " is not a finite number: ignored.");
  }
  else
  {
    vtkWarningWithObjectMacro(object,
      << parameter << " " << value << " is not a finite number: ignored, " << parameter
      << " stays " << kept << ".");
  }
  return false;
}

#define vtkSetFiniteClampMacro(name, type, min, max)                                              \
  virtual void Set##name(type _arg)                                                               \
  {                                                                                               \
    if (!vtkShadowMapsIsFiniteParameter(this, #name, _arg, this->name))                           \
    {                                                                                             \
      return;                                                                                     \
    }                                                                                             \
    const type clamped = _arg < (min) ? (min) : (_arg > (max) ? (max) : _arg);                    \
    if (this->name != clamped)                                                                    \
    {                                                                                             \
      this->name = clamped;                                                                       \
      this->Modified();                                                                           \
    }                                                                                             \
  }                                                                                               \
  virtual type Get##name##MinValue() { return min; }                                              \
  virtual type Get##name##MaxValue() { return max; }

#endif
