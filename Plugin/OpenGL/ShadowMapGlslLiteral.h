// Numbers written into GLSL source (#define'd parameters): a literal GLSL
// parses as a float whatever the value.
#ifndef ShadowMapGlslLiteral_h
#define ShadowMapGlslLiteral_h

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace shadowmaps
{
/// `value` as a GLSL float literal: a decimal point always (an int literal
/// does not convert in every context), nine significant digits, an exponent
/// where needed ("1.00000000e+30"), within +-1e38 (a literal beyond float's
/// range may not compile), and 0.0 for NaN (setters refuse it; computed values may
/// still be).
inline std::string GlslFloat(double value)
{
  const double largest = 1e38;
  const double finite = std::isnan(value) ? 0.0 : std::min(std::max(value, -largest), largest);
  std::ostringstream literal;
  literal.imbue(std::locale::classic());
  literal.precision(9);
  literal << std::showpoint << finite;
  return literal.str();
}
} // namespace shadowmaps

#endif
