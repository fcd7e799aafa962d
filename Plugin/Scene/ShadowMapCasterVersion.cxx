#include "ShadowMapCasterVersion.h"

#include "ShadowMapFocusing.h"
#include "ShadowMapPropParts.h"

#include "vtkAbstractMapper.h"
#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkDataObject.h"
#include "vtkFollower.h"
#include "vtkMatrix4x4.h"
#include "vtkPlaneCollection.h"
#include "vtkProp.h"
#include "vtkProp3D.h"
#include "vtkProp3DFollower.h"
#include "vtkProperty.h"

#include <algorithm>
#include <cstring>

namespace shadowmaps
{
namespace
{
// An FNV-style mix of 64-bit words: versions are compared for equality only.
class VersionHash
{
public:
  void Add(vtkMTimeType word)
  {
    this->Value = (this->Value ^ word) * 1099511628211ull;
    this->Value ^= this->Value >> 29;
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

// Every input connection of every port, updated first (where it is not
// known to be), and the mapper itself.
void AddMapper(vtkAbstractMapper* mapper, bool firstInputsUpdated, VersionHash& hash)
{
  hash.Add(mapper->GetMTime());
  for (int port = 0; port < mapper->GetNumberOfInputPorts(); ++port)
  {
    for (int connection = 0; connection < mapper->GetNumberOfInputConnections(port); ++connection)
    {
      vtkAlgorithm* producer = mapper->GetInputAlgorithm(port, connection);
      if (producer && !(port == 0 && firstInputsUpdated))
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

bool DrawsImpostors(vtkProp* part)
{
  auto* actor = vtkActor::SafeDownCast(part);
  vtkProperty* property = actor ? actor->GetProperty() : nullptr;
  return property && (property->GetRenderPointsAsSpheres() || property->GetRenderLinesAsTubes());
}
} // namespace

//------------------------------------------------------------------------------
vtkMTimeType CasterVersion(
  vtkProp* prop, bool firstInputsUpdated, const ImpostorSizing& impostorSizing)
{
  VersionHash hash;
  bool assembled = false;
  ForEachPart(prop, [&](vtkProp* part, vtkMatrix4x4* pathMatrix) {
    if (part != prop)
    {
      // Assemblies poke each part's matrix, which modifies it, at every
      // draw: a part is known by its composed and own matrices' values and its
      // visibility, not by its modification time.
      assembled = true;
      hash.Add(static_cast<vtkMTimeType>(part->GetVisibility()));
      if (auto* actor = vtkActor::SafeDownCast(part))
      {
        // Its point size or line width sizes its impostors.
        hash.Add(actor->GetProperty()->GetMTime());
      }
      AddMatrix(pathMatrix, hash);
      if (auto* placed = vtkProp3D::SafeDownCast(part))
      {
        AddMatrix(placed->GetMatrix(), hash);
      }
    }
    else if (vtkFollower::SafeDownCast(part) || vtkProp3DFollower::SafeDownCast(part))
    {
      // A follower's matrix follows its camera, which no modification time records.
      AddMatrix(vtkProp3D::SafeDownCast(part)->GetMatrix(), hash);
    }
    if (vtkAbstractMapper* mapper = MapperOf(part))
    {
      AddMapper(mapper, firstInputsUpdated, hash);
    }
    if (DrawsImpostors(part))
    {
      for (const double value : impostorSizing)
      {
        hash.Add(value);
      }
    }
  });
  if (!assembled)
  {
    // An actor's redraw time is its own (with its properties and texture), its
    // mapper's and its input's, which AddMapper has; vtkActor::GetRedrawMTime
    // would update the input once more.
    hash.Add(vtkActor::SafeDownCast(prop) ? prop->GetMTime() : prop->GetRedrawMTime());
  }
  else if (auto* placed = vtkProp3D::SafeDownCast(prop))
  {
    AddMatrix(placed->GetMatrix(), hash);
  }
  return hash.Get();
}

//------------------------------------------------------------------------------
double ImpostorReach(vtkProp* prop, const Aabb& bounds, const ImpostorSizing& impostorSizing)
{
  float largestSize = 0.0f;
  ForEachPart(prop, [&](vtkProp* part, vtkMatrix4x4*) {
    if (DrawsImpostors(part))
    {
      vtkProperty* property = vtkActor::SafeDownCast(part)->GetProperty();
      largestSize = std::max({ largestSize,
        property->GetRenderPointsAsSpheres() ? property->GetPointSize() : 0.0f,
        property->GetRenderLinesAsTubes() ? property->GetLineWidth() : 0.0f });
    }
  });
  const double perEyeDepth = largestSize / (impostorSizing[0] * impostorSizing[1]);
  if (!(perEyeDepth > 0.0) || !bounds.IsUsable())
  {
    return 0.0;
  }
  if (impostorSizing[6] != 0.0)
  {
    return perEyeDepth; // a parallel camera's impostors do not grow with depth
  }
  // The eye depth is minus the view's z row (VTK's cameras look down -z).
  double farthest = 0.0;
  for (const auto& corner : bounds.Corners())
  {
    farthest = std::max(farthest, -(impostorSizing[2] * corner.x + impostorSizing[3] * corner.y +
        impostorSizing[4] * corner.z + impostorSizing[5]));
  }
  return perEyeDepth * farthest;
}
} // namespace shadowmaps
