// Which shader programs got a set of uniforms since it last changed. Programs
// keep their uniforms, and many draws share one program (VTK's shader cache
// gives identical sources one program): setting them on a program's first use
// after a change, not for every draw, keeps the per-draw cost of the passes
// independent of the number of lights and views.
#ifndef ShadowMapProgramStamps_h
#define ShadowMapProgramStamps_h

#include "vtkShaderProgram.h"

#include <unordered_map>
#include <utility>

namespace shadowmaps
{
class ProgramStamps
{
public:
  /// The uniforms changed: every program needs them again.
  void Invalidate() { ++this->Stamp; }

  /// True on a program's first use since the last Invalidate. A program
  /// rebuilt at the same address (new GL handle) counts as a new one.
  bool FirstUse(vtkShaderProgram* program)
  {
    const std::pair<unsigned int, unsigned long> stamp(program->GetHandle(), this->Stamp);
    auto found = this->Applied.find(program);
    if (found != this->Applied.end() && found->second == stamp)
    {
      return false;
    }
    this->Applied[program] = stamp;
    return true;
  }

  /// Forgets every program (e.g. when their GL resources are released).
  void Clear() { this->Applied.clear(); }

private:
  std::unordered_map<vtkShaderProgram*, std::pair<unsigned int, unsigned long>> Applied;
  unsigned long Stamp = 0;
};
} // namespace shadowmaps

#endif
