#include "ShadowMapVolumeReading.h"

#include "ShadowMapGlm.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace shadowmaps
{
namespace
{
// Why the way `volume` is drawn is not what the marcher models (empty: it is).
std::string UnmarchableDrawing(vtkVolume* volume)
{
  // A vtkMultiVolume's matrix and property are its first input's, in the
  // place of all of them (the class lives in a module the passes do not need).
  if (volume->IsA("vtkMultiVolume"))
  {
    return "a vtkMultiVolume";
  }
  auto* mapper = vtkVolumeMapper::SafeDownCast(volume->GetMapper());
  if (mapper && mapper->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND)
  {
    return "a volume drawn by another blend mode than composite";
  }
  if (mapper && mapper->GetCropping())
  {
    return "a volume with cropping";
  }
  vtkPlaneCollection* planes = volume->GetMapper()->GetClippingPlanes();
  if (planes && planes->GetNumberOfItems() > MostVolumeClippingPlanes)
  {
    return "a volume with more than " + std::to_string(MostVolumeClippingPlanes) +
      " clipping planes";
  }
  return std::string();
}

// The image and scalars `volume`'s mapper shows, when they can be marched;
// otherwise null, with why.
vtkImageData* MarchableImage(vtkVolume* volume, vtkDataArray*& scalars, std::string& why)
{
  vtkAbstractVolumeMapper* mapper = volume->GetMapper();
  auto* image = mapper ? vtkImageData::SafeDownCast(mapper->GetDataSetInput()) : nullptr;
  scalars = nullptr;
  if (!image)
  {
    why = "a volume of other data than image data";
    return nullptr;
  }
  why = UnmarchableDrawing(volume);
  if (!why.empty())
  {
    return nullptr;
  }
  int cellFlag = 0;
  scalars = vtkAbstractMapper::GetScalars(image, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  if (!scalars || cellFlag != 0 || scalars->GetNumberOfComponents() != 1)
  {
    why = "a volume whose scalars are not one component per point";
    scalars = nullptr;
    return nullptr;
  }
  vtkMatrix3x3* direction = image->GetDirectionMatrix();
  if (direction && !direction->IsIdentity())
  {
    why = "a volume of image data with a direction matrix";
    scalars = nullptr;
    return nullptr;
  }
  int dimensions[3];
  image->GetDimensions(dimensions);
  if (std::min({ dimensions[0], dimensions[1], dimensions[2] }) < 1 ||
    scalars->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    why = "a volume of empty image data";
    scalars = nullptr;
    return nullptr;
  }
  return image;
}
} // namespace

//------------------------------------------------------------------------------
void TabulateTransferFunctions(vtkVolume* volume, VolumeReading& reading)
{
  vtkVolumeProperty* property = volume->GetProperty();
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const bool rgb = property->GetColorChannels(0) == 3;
  reading.Table.resize(VolumeTableSize);
  for (int k = 0; k < VolumeTableSize; ++k)
  {
    const double s = reading.Low + (reading.High - reading.Low) * k / (VolumeTableSize - 1.0);
    glm::dvec3 color(1.0);
    if (rgb)
    {
      property->GetRGBTransferFunction(0)->GetColor(s, glm::value_ptr(color));
    }
    else
    {
      color = glm::dvec3(property->GetGrayTransferFunction(0)->GetValue(s));
    }
    reading.Table[k] = glm::dvec4(color, opacity->GetValue(s));
  }
}

//------------------------------------------------------------------------------
bool CanMarchVolume(vtkVolume* volume, std::string* why)
{
  vtkDataArray* scalars = nullptr;
  std::string reason;
  const bool can = volume->GetProperty() && MarchableImage(volume, scalars, reason);
  if (why)
  {
    *why = volume->GetProperty() ? reason : "a volume without a property";
  }
  return can;
}

//------------------------------------------------------------------------------
bool ReadVolumeLayout(vtkVolume* volume, VolumeReading& reading, std::string& why)
{
  if (!volume->GetMapper())
  {
    why = "a volume without a mapper";
    return false;
  }
  volume->GetMapper()->Update();
  reading.Image = volume->GetProperty() ? MarchableImage(volume, reading.Scalars, why) : nullptr;
  if (!reading.Image)
  {
    why = volume->GetProperty() ? why : "a volume without a property";
    return false;
  }
  int dimensions[3];
  reading.Image->GetDimensions(dimensions);
  reading.Dimensions = glm::ivec3(dimensions[0], dimensions[1], dimensions[2]);
  reading.Origin = ToGlm(reading.Image->GetOrigin());
  reading.Spacing = ToGlm(reading.Image->GetSpacing());
  double bounds[6];
  reading.Image->GetBounds(bounds);
  reading.BoxMin = glm::dvec3(bounds[0], bounds[2], bounds[4]);
  reading.BoxMax = glm::dvec3(bounds[1], bounds[3], bounds[5]);
  reading.DataToWorld = ToGlm(volume->GetMatrix());
  const double* range = reading.Scalars->GetRange(0);
  reading.Low = std::isfinite(range[0]) ? range[0] : 0.0;
  reading.High = std::isfinite(range[1]) && range[1] > reading.Low ? range[1] : reading.Low + 1.0;
  vtkVolumeProperty* property = volume->GetProperty();
  reading.UnitDistance = std::max(property->GetScalarOpacityUnitDistance(0), 1e-30);
  reading.ClippingPlanes.clear();
  if (vtkPlaneCollection* planes = volume->GetMapper()->GetClippingPlanes())
  {
    planes->InitTraversal();
    while (vtkPlane* plane = planes->GetNextItem())
    {
      const glm::dvec3 normal = ToGlm(plane->GetNormal());
      reading.ClippingPlanes.emplace_back(normal, -glm::dot(normal, ToGlm(plane->GetOrigin())));
    }
  }
  const glm::dvec3 sides = glm::abs(reading.Spacing);
  const double smallest = std::min(sides.x, std::min(sides.y, sides.z));
  reading.Step = smallest > 0.0 ? smallest / VolumeStepsPerVoxel : 1.0;
  return true;
}

//------------------------------------------------------------------------------
bool ReadVolume(vtkVolume* volume, VolumeReading& reading, std::string& why)
{
  if (!ReadVolumeLayout(volume, reading, why))
  {
    return false;
  }
  TabulateTransferFunctions(volume, reading);
  return true;
}
} // namespace shadowmaps
