// The props a prop draws: itself, or an assembly's parts (vtkAssembly,
// vtkPropAssembly), each with the matrix its path composes.
#ifndef ShadowMapPropParts_h
#define ShadowMapPropParts_h

#include <functional>

class vtkAbstractMapper;
class vtkMatrix4x4;
class vtkProp;

namespace shadowmaps
{
/// Calls `visit` for every leaf of `prop`'s assembly paths with the matrix its
/// path composes (null where the path adds none).
void ForEachPart(vtkProp* prop, const std::function<void(vtkProp*, vtkMatrix4x4*)>& visit);

/// The mapper of an actor or a volume; null for other props.
vtkAbstractMapper* MapperOf(vtkProp* prop);

/// Makes every actor and volume `prop` draws build its shaders again at its
/// next draw (through its property, which leaves its buffers as they are).
void RebuildShaders(vtkProp* prop);
} // namespace shadowmaps

#endif
