#include "ShadowMapCasterVersion.h"

#include "ShadowMapPropParts.h"

#include "vtkAbstractMapper.h"
#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkDataObject.h"
#include "vtkMatrix4x4.h"
#include "vtkPlaneCollection.h"
#include "vtkProp.h"
#include "vtkProp3D.h"

#include <cstring>

namespace shadowmaps
{
namespace
{
// FNV-1a over 64-bit words: versions are compared for equality only.
class VersionHash
{
public:
  void Add(vtkMTimeType word)
  {
    for (int byte = 0; byte < 8; ++byte)
    {
      this->Value = (this->Value ^ ((word >> (8 * byte)) & 0xffu)) * 1099511628211ull;
    }
  }
  void Add(const double value)
  {
    vtkMTimeType bits = 0;
    std::memcpy(&bits, &value, sizeof(double));
    this->Add(bits);
  }
  vtkMTimeType Get() const { return this->Value; }

private:
  vtkMTimeType Value = 14695981039346656037ull;
};

// Every input connection of every port, updated first, and the mapper itself.
void AddMapper(vtkAbstractMapper* mapper, VersionHash& hash)
{
  hash.Add(mapper->GetMTime());
  for (int port = 0; port < mapper->GetNumberOfInputPorts(); ++port)
  {
    for (int connection = 0; connection < mapper->GetNumberOfInputConnections(port); ++connection)
    {
      if (vtkAlgorithm* producer = mapper->GetInputAlgorithm(port, connection))
      {
        producer->Update(mapper->GetInputConnection(port, connection)->GetIndex());
      }
      if (vtkDataObject* input = mapper->GetInputDataObject(port, connection))
      {
        hash.Add(input->GetMTime());
      }
    }
  }
  // The planes are watched, not only the collection: widgets move them in place.
  if (vtkPlaneCollection* planes = mapper->GetClippingPlanes())
  {
    hash.Add(planes->GetMTime());
    planes->InitTraversal();
    while (vtkObject* plane = planes->GetNextItemAsObject())
    {
      hash.Add(plane->GetMTime());
    }
  }
}

void AddMatrix(vtkMatrix4x4* matrix, VersionHash& hash)
{
  if (matrix)
  {
    const double* elements = matrix->GetData();
    for (int i = 0; i < 16; ++i)
    {
      hash.Add(elements[i]);
    }
  }
}

} // namespace

//------------------------------------------------------------------------------
vtkMTimeType CasterVersion(vtkProp* prop)
{
  VersionHash hash;
  hash.Add(prop->GetRedrawMTime());
  // Parts with their composed matrices: a follower's matrix follows its
  // camera, which no modification time records.
  ForEachPart(prop, [&hash](vtkProp* part, vtkMatrix4x4* pathMatrix) {
    hash.Add(part->GetRedrawMTime());
    AddMatrix(pathMatrix, hash);
    if (auto* placed = vtkProp3D::SafeDownCast(part))
    {
      AddMatrix(placed->GetMatrix(), hash);
    }
    if (vtkAbstractMapper* mapper = MapperOf(part))
    {
      AddMapper(mapper, hash);
    }
  });
  return hash.Get();
}
} // namespace shadowmaps
