#include "ShadowOracle.h"

#include "ShadowMapGlm.h"
#include "ShadowMapSceneReading.h"
#include "vtkAbstractShadowMapPass.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCompositeDataDisplayAttributes.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include "ShadowMapVTKCompat.h"
#include <vtkDataArray.h>
#include <vtkDataObjectTree.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDataSet.h>
#include <vtkGlyph3D.h>
#include <vtkGlyph3DMapper.h>
#include <vtkInformation.h>
#include <vtkInformationIntegerKey.h>
#include <vtkLight.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPointGaussianMapper.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProp.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVolume.h>
#include <vtkScalarsToColors.h>

#include "ShadowAreaLight.h"
#include "ShadowOracleVolumes.h"
#include "ShadowOracleEmbree.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iostream>
#include <limits>
#include <thread>

namespace shadoworacle
{
namespace
{

//------------------------------------------------------------------------------
// Embree handles

struct DeviceRelease
{
  void operator()(RTCDevice device) const { rtcReleaseDevice(device); }
};
struct SceneRelease
{
  void operator()(RTCScene scene) const { rtcReleaseScene(scene); }
};
using shadowmaps::ToGlm;
using DeviceHandle = std::unique_ptr<RTCDeviceTy, DeviceRelease>;
using SceneHandle = std::unique_ptr<RTCSceneTy, SceneRelease>;

std::string ErrorName(RTCError code)
{
  switch (code)
  {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
    default:
      return "unknown error";
  }
}

void Warn(const std::string& message)
{
  std::cerr << "shadoworacle: warning: " << message << '\n';
}

//------------------------------------------------------------------------------
// Triangles in world space, gathered from the renderer's actors

struct Mesh
{
  std::vector<float> Points; // x, y, z per point
  std::vector<unsigned> Triangles;
  std::vector<vtkIdType> TriangleCells; // the polydata cell each triangle comes from
  // Translucent meshes: colour and opacity at each triangle's corners, three
  // per triangle; empty for opaque ones.
  std::vector<glm::vec4> CornerColors;
};

bool SamePosition(const std::vector<float>& points, vtkIdType a, vtkIdType b)
{
  return points[3 * a] == points[3 * b] && points[3 * a + 1] == points[3 * b + 1] &&
    points[3 * a + 2] == points[3 * b + 2];
}

// Like VTK's index buffers, drops triangles with two points at the same place.
void AppendTriangle(Mesh& mesh, vtkIdType cell, vtkIdType a, vtkIdType b, vtkIdType c)
{
  if (SamePosition(mesh.Points, a, b) || SamePosition(mesh.Points, b, c) ||
    SamePosition(mesh.Points, a, c))
  {
    return;
  }
  mesh.Triangles.insert(mesh.Triangles.end(),
    { static_cast<unsigned>(a), static_cast<unsigned>(b), static_cast<unsigned>(c) });
  mesh.TriangleCells.push_back(cell);
}

// Calls function(cellId, size, ids) for each cell; ids count from firstCell,
// VTK's cell numbering of a polydata (vertices, lines, polygons, strips).
template <typename CellFunction>
void ForEachCell(vtkCellArray* cells, vtkIdType firstCell, CellFunction&& function)
{
  if (!cells)
  {
    return;
  }
  auto iter = vtk::TakeSmartPointer(cells->NewIterator());
  vtkIdType cell = firstCell;
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++cell)
  {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    iter->GetCurrentCell(size, ids);
    function(cell, size, ids);
  }
}

// VTK 9.1's OpenGL mappers draw a polygon as a fan around its first point
// (vtkOpenGLIndexBufferObject::AppendTriangleIndexBuffer): so does the oracle,
// which matters for non-planar polygons.
void AppendPolygons(vtkCellArray* polygons, vtkIdType firstCell, Mesh& mesh)
{
  ForEachCell(polygons, firstCell, [&mesh](vtkIdType cell, vtkIdType size, const vtkIdType* ids) {
    for (vtkIdType i = 1; i + 1 < size; ++i)
    {
      AppendTriangle(mesh, cell, ids[0], ids[i], ids[i + 1]);
    }
  });
}

void AppendStrips(vtkCellArray* strips, vtkIdType firstCell, Mesh& mesh)
{
  ForEachCell(strips, firstCell, [&mesh](vtkIdType cell, vtkIdType size, const vtkIdType* ids) {
    for (vtkIdType j = 0; j + 2 < size; ++j)
    {
      AppendTriangle(mesh, cell, ids[j], ids[j + 1 + j % 2], ids[j + 1 + (j + 1) % 2]);
    }
  });
}

Mesh WorldMesh(vtkPolyData* polyData, vtkMatrix4x4* matrix)
{
  Mesh mesh;
  vtkPoints* points = polyData->GetPoints();
  if (!points)
  {
    return mesh;
  }
  const vtkIdType count = points->GetNumberOfPoints();
  mesh.Points.reserve(3 * count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    double p[4] = { 0.0, 0.0, 0.0, 1.0 };
    points->GetPoint(i, p);
    double world[4];
    matrix->MultiplyPoint(p, world);
    for (int k = 0; k < 3; ++k)
    {
      mesh.Points.push_back(static_cast<float>(world[k] / world[3]));
    }
  }
  const vtkIdType firstPolygon = polyData->GetNumberOfVerts() + polyData->GetNumberOfLines();
  AppendPolygons(polyData->GetPolys(), firstPolygon, mesh);
  AppendStrips(polyData->GetStrips(), firstPolygon + polyData->GetNumberOfPolys(), mesh);
  return mesh;
}

// A polydata to trace, with what the composite mapper says of its block.
struct Part
{
  vtkSmartPointer<vtkPolyData> Data;
  bool HasOpacity = false; // a block opacity, drawn instead of the actor's
  double Opacity = 1.0;
  bool HasColor = false;  // a block colour, drawn instead of the property's
  glm::dvec3 Color{ 1.0 };
  bool MapsScalars = true; // glyph copies are coloured by the property only
};
using PartList = std::vector<Part>;

// The composite mapper lets a block inherit its parent's visibility, opacity
// and colour unless it has its own.
void CollectVisibleLeaves(vtkDataObject* object, vtkCompositeDataDisplayAttributes* attributes,
  bool visible, Part block, PartList& leaves)
{
  if (!object)
  {
    return;
  }
  if (attributes && attributes->HasBlockVisibility(object))
  {
    visible = attributes->GetBlockVisibility(object);
  }
  if (attributes && attributes->HasBlockOpacity(object))
  {
    block.HasOpacity = true;
    block.Opacity = attributes->GetBlockOpacity(object);
  }
  if (attributes && attributes->HasBlockColor(object))
  {
    block.HasColor = true;
    block.Color = ToGlm(attributes->GetBlockColor(object).GetData());
  }
  if (auto* tree = vtkDataObjectTree::SafeDownCast(object))
  {
    auto iter = vtk::TakeSmartPointer(tree->NewTreeIterator());
    iter->TraverseSubTreeOff();
    iter->VisitOnlyLeavesOff();
    for (iter->InitTraversal(); !iter->IsDoneWithTraversal(); iter->GoToNextItem())
    {
      CollectVisibleLeaves(iter->GetCurrentDataObject(), attributes, visible, block, leaves);
    }
    return;
  }
  auto* polyData = vtkPolyData::SafeDownCast(object);
  if (polyData && visible && block.Opacity > 0.0)
  {
    block.Data = polyData;
    leaves.push_back(block);
  }
}

PartList CompositeGeometry(vtkShadowCompositeMapper* mapper)
{
  mapper->Update();
  PartList leaves;
  CollectVisibleLeaves(mapper->GetInputDataObject(0, 0),
    mapper->GetCompositeDataDisplayAttributes(), true, Part(), leaves);
  return leaves;
}

std::vector<vtkDataSet*> DataSetsOf(vtkDataObject* object)
{
  std::vector<vtkDataSet*> dataSets;
  if (auto* dataSet = vtkDataSet::SafeDownCast(object))
  {
    dataSets.push_back(dataSet);
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(object))
  {
    auto iter = vtk::TakeSmartPointer(composite->NewIterator());
    for (iter->InitTraversal(); !iter->IsDoneWithTraversal(); iter->GoToNextItem())
    {
      if (auto* leaf = vtkDataSet::SafeDownCast(iter->GetCurrentDataObject()))
      {
        dataSets.push_back(leaf);
      }
    }
  }
  return dataSets;
}

// The point array an algorithm's input-array slot selects (by name or by
// attribute type), as vtkAlgorithm::GetInputArrayToProcess, which is protected.
vtkDataArray* SelectedPointArray(vtkAlgorithm* algorithm, int slot, vtkDataSet* data)
{
  vtkInformation* info = algorithm->GetInputArrayInformation(slot);
  vtkPointData* pointData = data->GetPointData();
  if (info->Has(vtkDataObject::FIELD_NAME()))
  {
    return pointData->GetArray(info->Get(vtkDataObject::FIELD_NAME()));
  }
  if (info->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    return pointData->GetAttribute(info->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE()));
  }
  return nullptr;
}

// Sets `glyph` up to place glyphs as vtkOpenGLGlyph3DMapper does: translate,
// rotate by 180 degrees about (v/|v| + x)/2, scale. vtkGlyph3D reads the scale
// from the active scalars or from the same vectors it orients by, so some
// mapper settings have no equivalent. Returns why, or an empty string.
std::string ConfigureGlyph(vtkGlyph3DMapper* mapper, vtkDataSet* points, vtkGlyph3D* glyph)
{
  if (mapper->GetUseSourceTableTree() || mapper->GetNumberOfInputConnections(1) > 1)
  {
    return "several glyph sources";
  }
  if (mapper->GetMasking() && SelectedPointArray(mapper, vtkGlyph3DMapper::MASK, points))
  {
    return "masking";
  }
  vtkDataArray* orientation = mapper->GetOrient()
    ? SelectedPointArray(mapper, vtkGlyph3DMapper::ORIENTATION, points)
    : nullptr;
  if (orientation &&
    (mapper->GetOrientationMode() != vtkGlyph3DMapper::DIRECTION ||
      orientation->GetNumberOfComponents() != 3))
  {
    return "orientation by rotation angles or quaternions";
  }
  const bool dataScaling =
    mapper->GetScaling() && mapper->GetScaleMode() != vtkGlyph3DMapper::NO_DATA_SCALING;
  vtkDataArray* scale =
    dataScaling ? SelectedPointArray(mapper, vtkGlyph3DMapper::SCALE, points) : nullptr;

  vtkDataArray* scalars = nullptr;
  vtkDataArray* vectors = orientation;
  int scaleMode = VTK_DATA_SCALING_OFF;
  if (scale)
  {
    const int components = scale->GetNumberOfComponents();
    const bool byMagnitude = mapper->GetScaleMode() == vtkGlyph3DMapper::SCALE_BY_MAGNITUDE;
    if (byMagnitude && components == 1)
    {
      // The mapper scales by |s|, vtkGlyph3D by s.
      if (scale->GetRange(0)[0] < 0.0)
      {
        return "negative scale factors";
      }
      scalars = scale;
      scaleMode = VTK_SCALE_BY_SCALAR;
    }
    else if ((components == 3 || (byMagnitude && components == 2)) &&
      (!orientation || orientation == scale))
    {
      vectors = scale;
      scaleMode = byMagnitude ? VTK_SCALE_BY_VECTOR : VTK_SCALE_BY_VECTORCOMPONENTS;
    }
    else
    {
      return "scaling by an array other than the orientation array";
    }
  }

  auto input = vtk::TakeSmartPointer(points->NewInstance());
  input->CopyStructure(points);
  if (scalars)
  {
    input->GetPointData()->SetScalars(scalars);
  }
  if (vectors)
  {
    input->GetPointData()->SetVectors(vectors);
  }
  glyph->SetInputData(input);
  glyph->SetSourceData(mapper->GetSource(0));
  glyph->SetScaling(mapper->GetScaling());
  glyph->SetScaleMode(scaleMode);
  glyph->SetScaleFactor(mapper->GetScaleFactor());
  glyph->SetRange(mapper->GetRange());
  glyph->SetClamping(mapper->GetClamping() && scale != nullptr);
  glyph->SetOrient(orientation != nullptr);
  glyph->SetVectorModeToUseVector();
  glyph->SetIndexModeToOff();
  glyph->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  return {};
}

PartList GlyphGeometry(vtkGlyph3DMapper* mapper)
{
  mapper->Update();
  if (!mapper->GetSource(0))
  {
    return {}; // the default glyph is a line
  }
  PartList glyphs;
  for (vtkDataSet* points : DataSetsOf(mapper->GetInputDataObject(0, 0)))
  {
    vtkNew<vtkGlyph3D> glyph;
    const std::string unsupported = ConfigureGlyph(mapper, points, glyph);
    if (!unsupported.empty())
    {
      Warn("vtkGlyph3DMapper with " + unsupported + " is not reproduced: skipped");
      return {};
    }
    glyph->Update();
    Part copies;
    copies.Data = glyph->GetOutput();
    copies.MapsScalars = false;
    glyphs.push_back(copies);
  }
  return glyphs;
}

PartList MapperGeometry(vtkMapper* mapper)
{
  if (auto* composite = vtkShadowCompositeMapper::SafeDownCast(mapper))
  {
    return CompositeGeometry(composite);
  }
  if (vtkPointGaussianMapper::SafeDownCast(mapper))
  {
    Warn("vtkPointGaussianMapper draws splats, not polygons: skipped");
    return {};
  }
  if (auto* polyDataMapper = vtkPolyDataMapper::SafeDownCast(mapper))
  {
    polyDataMapper->Update();
    if (vtkPolyData* input = polyDataMapper->GetInput())
    {
      Part whole;
      whole.Data = input;
      return { whole };
    }
    return {};
  }
  if (auto* glyphMapper = vtkGlyph3DMapper::SafeDownCast(mapper))
  {
    return GlyphGeometry(glyphMapper);
  }
  Warn(std::string(mapper->GetClassName()) + " is not supported: skipped");
  return {};
}

// The passes' own opt-out rule.
bool CastsShadows(vtkProp* prop)
{
  return shadowmaps::TakesPart(prop, vtkAbstractShadowMapPass::CASTS_SHADOWS());
}

bool IsVisibleCaster(vtkActor* actor)
{
  return actor->GetVisibility() && actor->GetMapper() && actor->GetProperty()->GetOpacity() > 0.0 &&
    CastsShadows(actor);
}

// The mapper's scalars as VTK colours them (RGBA, alpha from the lookup
// table), or null where it draws without them. cellFlag: 0 per point, 1 per
// cell; field-data colours (one tuple for everything) are left out.
vtkSmartPointer<vtkUnsignedCharArray> MappedScalars(vtkMapper* mapper, vtkDataSet* data, int& cellFlag)
{
  cellFlag = 0;
  if (!mapper->GetScalarVisibility())
  {
    return nullptr;
  }
  vtkAbstractArray* scalars = vtkAbstractMapper::GetAbstractScalars(data, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  if (!scalars || cellFlag > 1)
  {
    return nullptr;
  }
  return vtk::TakeSmartPointer(
    mapper->GetLookupTable()->MapScalars(scalars, mapper->GetColorMode(), -1));
}

glm::vec4 ColorOf(vtkUnsignedCharArray* colors, vtkIdType tuple, double opacity)
{
  const unsigned char* rgba = colors->GetPointer(4 * tuple);
  return { rgba[0] / 255.0f, rgba[1] / 255.0f, rgba[2] / 255.0f,
    static_cast<float>(opacity * rgba[3] / 255.0) };
}

// The colour and opacity VTK draws at each triangle corner: the mapped
// scalars (their alpha times the opacity), or the block's or the property's
// diffuse colour with the opacity, the block's in place of the actor's where
// it has one. Textures are not read.
void ColorCorners(Mesh& mesh, const Part& part, vtkMapper* mapper, vtkProperty* property)
{
  const double opacity = part.HasOpacity ? part.Opacity : property->GetOpacity();
  const glm::vec4 uniform(
    part.HasColor ? part.Color : ToGlm(property->GetDiffuseColor()), opacity);
  int cellFlag = 0;
  vtkSmartPointer<vtkUnsignedCharArray> colors =
    part.MapsScalars ? MappedScalars(mapper, part.Data, cellFlag) : nullptr;
  if (colors && colors->GetNumberOfComponents() != 4)
  {
    colors = nullptr;
  }
  mesh.CornerColors.clear();
  mesh.CornerColors.reserve(mesh.Triangles.size());
  for (std::size_t t = 0; t < mesh.TriangleCells.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType tuple = cellFlag == 1 ? mesh.TriangleCells[t] : mesh.Triangles[3 * t + k];
      mesh.CornerColors.push_back(colors ? ColorOf(colors, tuple, opacity) : uniform);
    }
  }
}

bool IsTranslucent(const Mesh& mesh)
{
  return std::any_of(mesh.CornerColors.begin(), mesh.CornerColors.end(),
    [](const glm::vec4& rgba) { return rgba.a < 1.0f; });
}

// The renderer's casters split into opaque and translucent meshes, and its
// volumes.
struct CasterGeometry
{
  std::vector<Mesh> Opaque;
  std::vector<Mesh> Translucent;
  std::vector<MarchedVolume> Volumes;
};

void AddVolume(vtkVolume* volume, CasterGeometry& casters)
{
  if (!volume->GetVisibility() || !CastsShadows(volume))
  {
    return;
  }
  MarchedVolume marched;
  std::string why;
  if (MarchedVolume::FromVolume(volume, marched, why))
  {
    casters.Volumes.push_back(std::move(marched));
  }
  else
  {
    Warn(why + " is not marched: skipped");
  }
}

CasterGeometry CasterMeshes(vtkRenderer* renderer)
{
  CasterGeometry casters;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator iter;
  props->InitTraversal(iter);
  while (vtkProp* prop = props->GetNextProp(iter))
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    if (auto* volume = vtkVolume::SafeDownCast(prop))
    {
      AddVolume(volume, casters);
      continue;
    }
    if (!actor)
    {
      if (prop->GetVisibility() && prop->IsA("vtkAssembly"))
      {
        Warn("vtkAssembly is not supported: skipped");
      }
      continue;
    }
    if (!IsVisibleCaster(actor))
    {
      continue;
    }
    if (actor->GetTexture() && actor->GetTexture()->IsTranslucent())
    {
      Warn("a texture's alpha is not reproduced: its actor traced with its property's opacity");
    }
    for (const Part& part : MapperGeometry(actor->GetMapper()))
    {
      Mesh mesh = WorldMesh(part.Data, actor->GetMatrix());
      if (mesh.Triangles.empty())
      {
        continue;
      }
      ColorCorners(mesh, part, actor->GetMapper(), actor->GetProperty());
      if (IsTranslucent(mesh))
      {
        casters.Translucent.push_back(std::move(mesh));
      }
      else
      {
        mesh.CornerColors.clear();
        casters.Opaque.push_back(std::move(mesh));
      }
    }
  }
  return casters;
}

std::size_t CountTriangles(const std::vector<Mesh>& meshes)
{
  std::size_t count = 0;
  for (const Mesh& mesh : meshes)
  {
    count += mesh.Triangles.size() / 3;
  }
  return count;
}

double SurfaceOffsetOf(const std::vector<const Mesh*>& meshes)
{
  glm::dvec3 low(std::numeric_limits<double>::max());
  glm::dvec3 high(std::numeric_limits<double>::lowest());
  for (const Mesh* mesh : meshes)
  {
    for (std::size_t i = 0; i < mesh->Points.size(); i += 3)
    {
      const glm::dvec3 p(mesh->Points[i], mesh->Points[i + 1], mesh->Points[i + 2]);
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  }
  const glm::dvec3 largest = glm::max(glm::abs(low), glm::abs(high));
  const double size =
    std::max(glm::length(high - low), std::max(largest.x, std::max(largest.y, largest.z)));
  return 1e-5 * size;
}

//------------------------------------------------------------------------------
// Camera, lights, rays

struct CameraFrame
{
  glm::dmat4 ClipToWorld;
  glm::dvec3 Position;
  glm::dvec3 Direction; // unit direction of projection
  bool Parallel = false;
  double DepthRange = 0.0; // far - near clipping distance
};

// The same matrix vtkOpenGLCamera::GetKeyMatrices gives the rasteriser.
CameraFrame MakeCameraFrame(vtkRenderer* renderer, int width, int height)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  const double aspect = static_cast<double>(width) / height;
  CameraFrame frame;
  frame.ClipToWorld =
    glm::inverse(ToGlm(camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0)));
  frame.Position = ToGlm(camera->GetPosition());
  frame.Direction = glm::normalize(ToGlm(camera->GetDirectionOfProjection()));
  frame.Parallel = camera->GetParallelProjection() != 0;
  const double* range = camera->GetClippingRange();
  frame.DepthRange = range[1] - range[0];
  return frame;
}

glm::dvec3 Unproject(const glm::dmat4& clipToWorld, const glm::dvec3& ndc)
{
  const glm::dvec4 p = clipToWorld * glm::dvec4(ndc, 1.0);
  return glm::dvec3(p) / p.w;
}

glm::dvec2 PixelCentreNdc(int x, int y, int width, int height)
{
  return { 2.0 * (x + 0.5) / width - 1.0, 2.0 * (y + 0.5) / height - 1.0 };
}

double ViewDepth(const CameraFrame& camera, const glm::dvec3& point)
{
  return glm::dot(point - camera.Position, camera.Direction);
}

// Directions need not be unit length: a hit lies at Origin + t * Direction,
// 0 <= t <= Far.
struct Ray
{
  glm::dvec3 Origin;
  glm::dvec3 Direction;
  double Far;
};

// From the near to the far clipping plane: t runs from 0 to 1.
Ray PrimaryRay(const CameraFrame& camera, int x, int y, int width, int height)
{
  const glm::dvec2 ndc = PixelCentreNdc(x, y, width, height);
  const glm::dvec3 nearPoint = Unproject(camera.ClipToWorld, glm::dvec3(ndc, -1.0));
  const glm::dvec3 farPoint = Unproject(camera.ClipToWorld, glm::dvec3(ndc, 1.0));
  return { nearPoint, farPoint - nearPoint, 1.0 };
}

RTCRay ToEmbree(const Ray& ray)
{
  RTCRay result{};
  result.org_x = static_cast<float>(ray.Origin.x);
  result.org_y = static_cast<float>(ray.Origin.y);
  result.org_z = static_cast<float>(ray.Origin.z);
  result.dir_x = static_cast<float>(ray.Direction.x);
  result.dir_y = static_cast<float>(ray.Direction.y);
  result.dir_z = static_cast<float>(ray.Direction.z);
  result.tnear = 0.0f;
  result.tfar = static_cast<float>(ray.Far);
  result.mask = 0xFFFFFFFFu;
  return result;
}

struct LightFrame
{
  bool Usable = false;
  bool Positional = false;
  bool Spot = false;
  glm::dvec3 Position{ 0.0 };    // positional lights
  glm::dvec3 TowardLight{ 0.0 }; // directional lights: unit vector toward the light
  glm::dvec3 Axis{ 0.0 };        // spot lights: unit vector from the light to its focal point
  double CosCone = -1.0;
};

LightFrame MakeLightFrame(vtkLight* light)
{
  LightFrame frame;
  const glm::dvec3 position = ToGlm(light->GetTransformedPosition());
  const glm::dvec3 focalPoint = ToGlm(light->GetTransformedFocalPoint());
  const double length = glm::length(position - focalPoint);
  frame.Positional = light->GetPositional() != 0;
  frame.Position = position;
  // VTK: a positional light with a cone angle (a half angle) of 90 degrees or
  // more lights every direction.
  frame.Spot = frame.Positional && light->GetConeAngle() < 90.0;
  if (length > 0.0)
  {
    frame.TowardLight = (position - focalPoint) / length;
    frame.Axis = -frame.TowardLight;
  }
  frame.Usable = frame.Positional ? (!frame.Spot || length > 0.0) : length > 0.0;
  frame.CosCone = std::cos(glm::radians(light->GetConeAngle()));
  return frame;
}

// Runs rowFunction(y) for every row on all cores; each row is computed by
// one thread, so results do not depend on scheduling.
template <typename RowFunction>
void ForEachRow(int height, RowFunction&& rowFunction)
{
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned threadCount = std::min<unsigned>(cores, static_cast<unsigned>(height));
  std::atomic<int> nextRow{ 0 };
  auto work = [&]() {
    for (int y = nextRow++; y < height; y = nextRow++)
    {
      rowFunction(y);
    }
  };
  std::vector<std::thread> threads;
  for (unsigned i = 1; i < threadCount; ++i)
  {
    threads.emplace_back(work);
  }
  work();
  for (std::thread& thread : threads)
  {
    thread.join();
  }
}

Surface EmptySurface(int width, int height)
{
  Surface surface;
  surface.Width = std::max(0, width);
  surface.Height = std::max(0, height);
  const std::size_t count = static_cast<std::size_t>(surface.Width) * surface.Height;
  surface.Valid.assign(count, 0);
  surface.Position.assign(count, glm::dvec3(0.0));
  surface.Normal.assign(count, glm::dvec3(0.0));
  surface.ViewDepth.assign(count, 0.0);
  surface.SeenThroughTranslucent.assign(count, 0);
  return surface;
}

struct Hit
{
  glm::dvec3 Position;
  glm::dvec3 Normal; // unit, facing the ray's origin
};

// Embree's buffers of one attached geometry.
struct TriangleBuffers
{
  const float* Points = nullptr;
  const unsigned* Triangles = nullptr;
};

// One Embree scene and what the oracle keeps of its geometries.
struct TracedScene
{
  SceneHandle Scene;
  std::vector<TriangleBuffers> Geometries; // by geometry id; owned by Scene
  // Translucent scenes: colour and opacity at each triangle's corners.
  std::vector<std::vector<glm::vec4>> CornerColors; // by geometry id
};

// What the light a ray carries keeps after its translucent crossings, and
// how many rays of a sample there were and whether they all agreed.
struct LightSample
{
  glm::dvec3 Sum{ 0.0 };
  int Rays = 0;
  bool Agree = true;
};

} // namespace

//------------------------------------------------------------------------------
glm::dvec3 SurfaceTransmittance(const glm::dvec3& color, double opacity)
{
  const double a = std::min(1.0, std::max(0.0, opacity));
  const glm::dvec3 c = glm::clamp(color, 0.0, 1.0);
  return (1.0 - a) * ((1.0 - a) + a * c);
}

//------------------------------------------------------------------------------
struct Oracle::Impl
{
  DeviceHandle Device;
  TracedScene Opaque;
  TracedScene Translucent; // no Scene without translucent casters
  std::vector<MarchedVolume> Volumes;
  std::size_t NumberOfTriangles = 0;
  std::size_t NumberOfTranslucentTriangles = 0;
  double SurfaceOffset = 0.0;

  // A ray crosses at most this many translucent surfaces; past them its light
  // is taken as spent.
  static constexpr int MostCrossings = 1024;

  void Clear()
  {
    this->Opaque = TracedScene();
    this->Translucent = TracedScene();
    this->Volumes.clear();
    this->NumberOfTriangles = 0;
    this->NumberOfTranslucentTriangles = 0;
    this->SurfaceOffset = 0.0;
  }

  bool EnsureDevice(std::string& error)
  {
    if (!this->Device)
    {
      this->Device.reset(rtcNewDevice(nullptr));
      if (!this->Device)
      {
        error = "Embree: cannot create a device (" + ErrorName(rtcGetDeviceError(nullptr)) + ")";
        return false;
      }
    }
    return true;
  }

  std::string DeviceError(const std::string& what) const
  {
    return "Embree: cannot " + what + " (" + ErrorName(rtcGetDeviceError(this->Device.get())) + ")";
  }

  bool Attach(TracedScene& traced, const Mesh& mesh)
  {
    RTCGeometry geometry = rtcNewGeometry(this->Device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry)
    {
      return false;
    }
    const std::size_t pointCount = mesh.Points.size() / 3;
    const std::size_t triangleCount = mesh.Triangles.size() / 3;
    auto* points = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX,
      0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), pointCount));
    auto* triangles = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry,
      RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangleCount));
    if (!points || !triangles)
    {
      rtcReleaseGeometry(geometry);
      return false;
    }
    std::copy(mesh.Points.begin(), mesh.Points.end(), points);
    std::copy(mesh.Triangles.begin(), mesh.Triangles.end(), triangles);
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(traced.Scene.get(), geometry);
    rtcReleaseGeometry(geometry); // the scene keeps it
    if (id >= traced.Geometries.size())
    {
      traced.Geometries.resize(id + 1);
      traced.CornerColors.resize(id + 1);
    }
    traced.Geometries[id] = { points, triangles };
    traced.CornerColors[id] = mesh.CornerColors;
    return true;
  }

  // A BVH of the meshes in `traced`; false with `error` if Embree fails.
  bool BuildScene(const std::vector<Mesh>& meshes, TracedScene& traced, std::string& error)
  {
    traced = TracedScene();
    traced.Scene.reset(rtcNewScene(this->Device.get()));
    if (!traced.Scene)
    {
      error = this->DeviceError("create a scene");
      return false;
    }
    // ROBUST: no optimisations that trade accuracy for speed; this is ground truth.
    rtcSetSceneFlags(traced.Scene.get(), RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(traced.Scene.get(), RTC_BUILD_QUALITY_HIGH);
    for (const Mesh& mesh : meshes)
    {
      if (!this->Attach(traced, mesh))
      {
        error = this->DeviceError("create a triangle geometry");
        return false;
      }
    }
    rtcCommitScene(traced.Scene.get());
    if (rtcGetDeviceError(this->Device.get()) != RTC_ERROR_NONE)
    {
      error = this->DeviceError("build the BVH");
      return false;
    }
    return true;
  }

  glm::dvec3 Point(const TriangleBuffers& buffers, unsigned index) const
  {
    const float* p = buffers.Points + 3 * static_cast<std::size_t>(index);
    return { p[0], p[1], p[2] };
  }

  // Embree's float hit distance is refined in double against the plane of the
  // triangle it hit, so hit points lie on the surface to double precision and
  // shadow rays can start a small, scale-relative distance off it.
  Hit MakeHit(const Ray& ray, const RTCRayHit& rayHit) const
  {
    const TriangleBuffers& buffers = this->Opaque.Geometries[rayHit.hit.geomID];
    const unsigned* triangle = buffers.Triangles + 3 * static_cast<std::size_t>(rayHit.hit.primID);
    const glm::dvec3 a = this->Point(buffers, triangle[0]);
    const glm::dvec3 normal =
      glm::cross(this->Point(buffers, triangle[1]) - a, this->Point(buffers, triangle[2]) - a);
    const double facing = glm::dot(ray.Direction, normal);
    double t = rayHit.ray.tfar;
    if (std::abs(facing) > 1e-9 * glm::length(ray.Direction) * glm::length(normal))
    {
      t = glm::dot(a - ray.Origin, normal) / facing;
    }
    Hit hit;
    hit.Position = ray.Origin + t * ray.Direction;
    hit.Normal = glm::normalize(facing > 0.0 ? -normal : normal);
    return hit;
  }

  // The nearest hit in `traced` along the ray from t = near; geomID is
  // invalid without one.
  static RTCRayHit Nearest(const TracedScene& traced, const Ray& ray, float near = 0.0f)
  {
    RTCRayHit rayHit{};
    rayHit.ray = ToEmbree(ray);
    rayHit.ray.tnear = near;
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    shadoworacle::IntersectNearest(traced.Scene.get(), rayHit);
    return rayHit;
  }

  // Where a ray that hit at t goes on, just beyond the hit.
  float Beyond(float t) const
  {
    const float next = t + std::max(t * 1e-6f, static_cast<float>(this->SurfaceOffset));
    return next > t ? next : std::nextafter(t, std::numeric_limits<float>::infinity());
  }

  // The nearest opaque hit along the ray, and whether a translucent caster
  // lies before it.
  bool Intersect(const Ray& ray, Hit& hit, bool& throughTranslucent) const
  {
    const RTCRayHit rayHit = Nearest(this->Opaque, ray);
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID)
    {
      return false;
    }
    hit = this->MakeHit(ray, rayHit);
    throughTranslucent = false;
    if (this->Translucent.Scene)
    {
      const RTCRayHit before = Nearest(this->Translucent, ray);
      throughTranslucent =
        before.hit.geomID != RTC_INVALID_GEOMETRY_ID && before.ray.tfar < rayHit.ray.tfar;
    }
    for (const MarchedVolume& volume : this->Volumes)
    {
      throughTranslucent = throughTranslucent || volume.Crosses(ray.Origin, ray.Direction, rayHit.ray.tfar);
    }
    return true;
  }

  bool Occluded(const Ray& ray) const
  {
    RTCRay shadowRay = ToEmbree(ray);
    shadoworacle::TestOcclusion(this->Opaque.Scene.get(), shadowRay);
    return shadowRay.tfar < 0.0f; // Embree sets -inf on a hit
  }

  // The colour and opacity at a translucent hit, interpolated between the
  // triangle's corners as the rasteriser interpolates vertex colours.
  glm::dvec4 ColorAt(const RTCHit& hit) const
  {
    const std::vector<glm::vec4>& corners = this->Translucent.CornerColors[hit.geomID];
    const std::size_t first = 3 * static_cast<std::size_t>(hit.primID);
    return glm::dvec4(corners[first]) * static_cast<double>(1.0f - hit.u - hit.v) +
      glm::dvec4(corners[first + 1]) * static_cast<double>(hit.u) +
      glm::dvec4(corners[first + 2]) * static_cast<double>(hit.v);
  }

  // The product of SurfaceTransmittance over every translucent surface the
  // ray crosses, each once, in any order.
  glm::dvec3 TranslucentProduct(const Ray& ray) const
  {
    glm::dvec3 product(1.0);
    if (!this->Translucent.Scene)
    {
      return product;
    }
    float near = 0.0f;
    for (int crossing = 0; crossing < MostCrossings; ++crossing)
    {
      const RTCRayHit rayHit = Nearest(this->Translucent, ray, near);
      if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID)
      {
        return product;
      }
      const glm::dvec4 rgba = this->ColorAt(rayHit.hit);
      product *= SurfaceTransmittance(glm::dvec3(rgba), rgba.a);
      if (product == glm::dvec3(0.0))
      {
        return product;
      }
      near = this->Beyond(rayHit.ray.tfar);
    }
    return glm::dvec3(0.0);
  }

  // What of the light reaches the ray's end, per channel.
  glm::dvec3 Transmittance(const Ray& ray) const
  {
    if (this->Occluded(ray))
    {
      return glm::dvec3(0.0);
    }
    glm::dvec3 product = this->TranslucentProduct(ray);
    for (const MarchedVolume& volume : this->Volumes)
    {
      product *= volume.Transmittance(ray.Origin, ray.Direction, ray.Far);
    }
    return product;
  }

  // Distinct geometries along the ray, up to `most`: each hit restarts the
  // ray just beyond it.
  int CountGeometries(const Ray& ray, int most) const
  {
    std::vector<unsigned> seen;
    float near = 0.0f;
    while (static_cast<int>(seen.size()) < most)
    {
      const RTCRayHit rayHit = Nearest(this->Opaque, ray, near);
      if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID)
      {
        break;
      }
      if (std::find(seen.begin(), seen.end(), rayHit.hit.geomID) == seen.end())
      {
        seen.push_back(rayHit.hit.geomID);
      }
      near = this->Beyond(rayHit.ray.tfar);
    }
    return static_cast<int>(seen.size());
  }

  // The occlusion ray of a surface point toward the light; false where the
  // point is not counted (behind the light, outside a spot's cone, facing away).
  bool ShadowRay(const LightFrame& light, const glm::dvec3& position, const glm::dvec3& normal,
    double minimumCosine, Ray& ray) const
  {
    const glm::dvec3 origin = position + this->SurfaceOffset * normal;
    ray = Ray{ origin, light.TowardLight, std::numeric_limits<double>::infinity() };
    if (light.Positional)
    {
      const glm::dvec3 toLight = light.Position - position;
      const double distance = glm::length(toLight);
      if (distance <= 0.0)
      {
        return false;
      }
      if (light.Spot && glm::dot(-toLight / distance, light.Axis) < light.CosCone)
      {
        return false;
      }
      ray.Direction = glm::normalize(light.Position - origin);
      ray.Far = std::max(0.0, glm::length(light.Position - origin) - this->SurfaceOffset);
    }
    const glm::dvec3 towardLight =
      light.Positional ? glm::normalize(light.Position - position) : light.TowardLight;
    return glm::dot(normal, towardLight) > minimumCosine;
  }

  // Sums rayValue(ray) (a dvec3) over `count` stratified rays from the point
  // toward a light of `size` (its GetLightSize; 0: the one ray to its
  // centre); false where the point is not counted.
  template <typename RayValue>
  bool SampleLight(const LightFrame& light, double size, const glm::dvec3& position,
    const glm::dvec3& normal, double minimumCosine, int count, std::uint64_t seed,
    RayValue&& rayValue, LightSample& sample) const
  {
    sample = LightSample();
    Ray centreRay;
    if (!this->ShadowRay(light, position, normal, minimumCosine, centreRay))
    {
      return false;
    }
    if (!(size > 0.0))
    {
      sample.Sum = rayValue(centreRay);
      sample.Rays = 1;
      return true;
    }
    const shadowarealight::LightCone cone = light.Positional
      ? shadowarealight::SphereCone(centreRay.Origin, light.Position, size)
      : shadowarealight::SunCone(light.TowardLight, size);
    sample.Rays = count;
    if (cone.Inside)
    {
      sample.Sum = glm::dvec3(count);
      return true;
    }
    const int strata = static_cast<int>(std::lround(std::sqrt(static_cast<double>(count))));
    glm::dvec3 first(0.0);
    for (int i = 0; i < count; ++i)
    {
      const shadowarealight::LightRay ray =
        shadowarealight::SampleCone(cone, centreRay.Origin, i, strata, seed);
      const double far =
        std::isinf(ray.Length) ? ray.Length : std::max(0.0, ray.Length - this->SurfaceOffset);
      const glm::dvec3 value = rayValue(Ray{ centreRay.Origin, ray.Direction, far });
      first = i == 0 ? value : first;
      sample.Agree = sample.Agree && value == first;
      sample.Sum += value;
    }
    return true;
  }

  // Per pixel, the mean of rayValue over a sized light's rays (NotCounted in
  // every channel where the pixel is not counted): CoarseRays first, then
  // RefinedRays where the rays disagree, or within two pixels of a pixel whose
  // rays disagree or whose mean differs.
  template <typename RayValue>
  std::vector<glm::vec3> SampleLightPerPixel(const Surface& surface, const LightFrame& frame,
    double size, double minimumCosine, VisibilityRays* rays, RayValue&& rayValue) const
  {
    const int width = surface.Width;
    const int height = surface.Height;
    const std::size_t count = surface.Valid.size();
    std::vector<glm::vec3> mean(count, glm::vec3(NotCounted));
    auto sample = [&](std::size_t i, int rayCount, std::uint64_t pass, LightSample& result) {
      return surface.Valid[i] &&
        this->SampleLight(frame, size, surface.Position[i], surface.Normal[i], minimumCosine,
          rayCount, shadowarealight::Mix(i, pass), rayValue, result);
    };
    auto average = [](const LightSample& s) {
      return glm::vec3(static_cast<float>(s.Sum.x) / s.Rays, static_cast<float>(s.Sum.y) / s.Rays,
        static_cast<float>(s.Sum.z) / s.Rays);
    };
    std::vector<LightSample> coarse(count);
    std::vector<unsigned char> counted(count, 0);
    ForEachRow(height, [&](int y) {
      for (int x = 0; x < width; ++x)
      {
        const std::size_t i = static_cast<std::size_t>(y) * width + x;
        counted[i] = sample(i, CoarseRays, 0, coarse[i]) ? 1 : 0;
      }
    });
    constexpr int RefineReach = 2;
    const bool sized = size > 0.0;
    std::vector<LightSample> final(coarse);
    std::vector<unsigned char> refined(count, 0);
    ForEachRow(height, [&](int y) {
      for (int x = 0; x < width; ++x)
      {
        const std::size_t i = static_cast<std::size_t>(y) * width + x;
        if (!counted[i])
        {
          continue;
        }
        bool refine = sized && !coarse[i].Agree;
        for (int dy = -RefineReach; sized && dy <= RefineReach && !refine; ++dy)
        {
          for (int dx = -RefineReach; dx <= RefineReach && !refine; ++dx)
          {
            const int nx = x + dx;
            const int ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= width || ny >= height)
            {
              continue;
            }
            const std::size_t n = static_cast<std::size_t>(ny) * width + nx;
            refine = counted[n] && (!coarse[n].Agree || coarse[n].Sum != coarse[i].Sum);
          }
        }
        if (refine)
        {
          refined[i] = 1;
          sample(i, RefinedRays, 1, final[i]);
        }
        mean[i] = average(final[i]);
      }
    });
    if (rays)
    {
      for (std::size_t i = 0; i < count; ++i)
      {
        if (!counted[i])
        {
          continue;
        }
        ++rays->Counted;
        rays->Refined += refined[i];
        rays->Rays += coarse[i].Rays + (refined[i] ? final[i].Rays : 0);
        if (!final[i].Agree && (rays->FewestAtPartial == 0 || final[i].Rays < rays->FewestAtPartial))
        {
          rays->FewestAtPartial = final[i].Rays;
        }
      }
    }
    return mean;
  }

  Truth ClassifyPoint(const LightFrame& light, const glm::dvec3& position,
    const glm::dvec3& normal, double minimumCosine) const
  {
    Ray ray;
    if (!this->ShadowRay(light, position, normal, minimumCosine, ray))
    {
      return Truth::Ignored;
    }
    return this->Occluded(ray) ? Truth::Shadowed : Truth::Lit;
  }
};

//------------------------------------------------------------------------------
Oracle::Oracle()
  : Pimpl(new Impl)
{
}

Oracle::~Oracle() = default;
Oracle::Oracle(Oracle&&) noexcept = default;
Oracle& Oracle::operator=(Oracle&&) noexcept = default;

std::size_t Oracle::GetNumberOfTriangles() const
{
  return this->Pimpl ? this->Pimpl->NumberOfTriangles : 0;
}

std::size_t Oracle::GetNumberOfTranslucentTriangles() const
{
  return this->Pimpl ? this->Pimpl->NumberOfTranslucentTriangles : 0;
}

std::size_t Oracle::GetNumberOfVolumes() const
{
  return this->Pimpl ? this->Pimpl->Volumes.size() : 0;
}

double Oracle::GetSurfaceOffset() const
{
  return this->Pimpl ? this->Pimpl->SurfaceOffset : 0.0;
}

//------------------------------------------------------------------------------
bool Oracle::Build(vtkRenderer* renderer, std::string& error)
{
  if (!this->Pimpl)
  {
    this->Pimpl.reset(new Impl); // a moved-from oracle can be rebuilt
  }
  Impl& impl = *this->Pimpl;
  impl.Clear();
  if (!renderer)
  {
    error = "no renderer";
    return false;
  }
  const CasterGeometry casters = CasterMeshes(renderer);
  if (CountTriangles(casters.Opaque) == 0)
  {
    error = "the renderer has no visible, opaque, shadow-casting triangles";
    return false;
  }
  if (!impl.EnsureDevice(error) || !impl.BuildScene(casters.Opaque, impl.Opaque, error) ||
    (!casters.Translucent.empty() &&
      !impl.BuildScene(casters.Translucent, impl.Translucent, error)))
  {
    impl.Clear();
    return false;
  }
  impl.NumberOfTriangles = CountTriangles(casters.Opaque);
  impl.NumberOfTranslucentTriangles = CountTriangles(casters.Translucent);
  impl.Volumes = casters.Volumes;
  std::vector<const Mesh*> all;
  for (const auto* meshes : { &casters.Opaque, &casters.Translucent })
  {
    for (const Mesh& mesh : *meshes)
    {
      all.push_back(&mesh);
    }
  }
  impl.SurfaceOffset = SurfaceOffsetOf(all);
  return true;
}

//------------------------------------------------------------------------------
Surface Oracle::Trace(vtkRenderer* renderer, int width, int height) const
{
  Surface surface = EmptySurface(width, height);
  if (!renderer || !this->Pimpl || !this->Pimpl->Opaque.Scene || surface.Valid.empty())
  {
    return surface;
  }
  const CameraFrame camera = MakeCameraFrame(renderer, width, height);
  const Impl& impl = *this->Pimpl;
  ForEachRow(height, [&](int y) {
    for (int x = 0; x < width; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      Hit hit;
      bool throughTranslucent = false;
      if (impl.Intersect(PrimaryRay(camera, x, y, width, height), hit, throughTranslucent))
      {
        surface.SeenThroughTranslucent[i] = throughTranslucent ? 1 : 0;
        surface.Valid[i] = 1;
        surface.Position[i] = hit.Position;
        surface.Normal[i] = hit.Normal;
        surface.ViewDepth[i] = ViewDepth(camera, hit.Position);
      }
    }
  });
  return surface;
}

//------------------------------------------------------------------------------
void Oracle::MaskRasterMismatch(Surface& surface, vtkRenderer* renderer,
  const std::vector<float>& zbuffer, double relativeTolerance)
{
  const std::size_t count = surface.Valid.size();
  if (!renderer || zbuffer.size() != count || count == 0)
  {
    std::cerr << "shadoworacle: MaskRasterMismatch: z-buffer of " << zbuffer.size()
              << " values for " << count << " pixels: every pixel dropped\n";
    std::fill(surface.Valid.begin(), surface.Valid.end(), 0);
    return;
  }
  const CameraFrame camera = MakeCameraFrame(renderer, surface.Width, surface.Height);
  for (int y = 0; y < surface.Height; ++y)
  {
    for (int x = 0; x < surface.Width; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * surface.Width + x;
      if (!surface.Valid[i])
      {
        continue;
      }
      if (zbuffer[i] >= 1.0f) // nothing rasterised here
      {
        surface.Valid[i] = 0;
        continue;
      }
      const glm::dvec2 ndc = PixelCentreNdc(x, y, surface.Width, surface.Height);
      const glm::dvec3 rasterPoint =
        Unproject(camera.ClipToWorld, glm::dvec3(ndc, 2.0 * zbuffer[i] - 1.0));
      const double scale = camera.Parallel ? camera.DepthRange : surface.ViewDepth[i];
      if (std::abs(ViewDepth(camera, rasterPoint) - surface.ViewDepth[i]) >
        relativeTolerance * scale)
      {
        surface.Valid[i] = 0;
      }
    }
  }
}

//------------------------------------------------------------------------------
std::vector<Truth> Oracle::Classify(
  const Surface& surface, vtkLight* light, double minimumCosine) const
{
  std::vector<Truth> truth(surface.Valid.size(), Truth::Ignored);
  if (!light || !this->Pimpl || !this->Pimpl->Opaque.Scene)
  {
    return truth;
  }
  const std::size_t count = static_cast<std::size_t>(std::max(0, surface.Width)) *
    static_cast<std::size_t>(std::max(0, surface.Height));
  if (surface.Valid.size() != count || surface.Position.size() != count ||
    surface.Normal.size() != count)
  {
    Warn("Classify: the surface's arrays do not hold Width x Height pixels: every pixel ignored");
    return truth;
  }
  const LightFrame frame = MakeLightFrame(light);
  if (!frame.Usable)
  {
    Warn("light has no direction (position equals focal point): every pixel ignored");
    return truth;
  }
  const Impl& impl = *this->Pimpl;
  ForEachRow(surface.Height, [&](int y) {
    for (int x = 0; x < surface.Width; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * surface.Width + x;
      if (surface.Valid[i])
      {
        truth[i] =
          impl.ClassifyPoint(frame, surface.Position[i], surface.Normal[i], minimumCosine);
      }
    }
  });
  return truth;
}

//------------------------------------------------------------------------------
std::vector<float> Oracle::Visibility(
  const Surface& surface, vtkLight* light, double minimumCosine, VisibilityRays* rays) const
{
  std::vector<float> visibility(surface.Valid.size(), NotCounted);
  if (rays)
  {
    *rays = VisibilityRays();
  }
  const Impl* impl = this->SampleableImpl(surface, light, minimumCosine);
  if (!impl)
  {
    return visibility;
  }
  const std::vector<glm::vec3> mean = impl->SampleLightPerPixel(surface, MakeLightFrame(light),
    vtkAbstractShadowMapPass::GetLightSize(light), minimumCosine, rays,
    [impl](const Ray& ray) { return impl->Occluded(ray) ? glm::dvec3(0.0) : glm::dvec3(1.0); });
  std::transform(mean.begin(), mean.end(), visibility.begin(), [](const glm::vec3& v) { return v.x; });
  return visibility;
}

//------------------------------------------------------------------------------
std::vector<glm::vec3> Oracle::Transmittance(
  const Surface& surface, vtkLight* light, double minimumCosine, VisibilityRays* rays) const
{
  if (rays)
  {
    *rays = VisibilityRays();
  }
  const Impl* impl = this->SampleableImpl(surface, light, minimumCosine);
  if (!impl)
  {
    return std::vector<glm::vec3>(surface.Valid.size(), glm::vec3(NotCounted));
  }
  return impl->SampleLightPerPixel(surface, MakeLightFrame(light),
    vtkAbstractShadowMapPass::GetLightSize(light), minimumCosine, rays,
    [impl](const Ray& ray) { return impl->Transmittance(ray); });
}

//------------------------------------------------------------------------------
const Oracle::Impl* Oracle::SampleableImpl(
  const Surface& surface, vtkLight* light, double minimumCosine) const
{
  const std::size_t count = static_cast<std::size_t>(std::max(0, surface.Width)) *
    static_cast<std::size_t>(std::max(0, surface.Height));
  if (!light || !this->Pimpl || !this->Pimpl->Opaque.Scene || surface.Valid.size() != count ||
    surface.Position.size() != count || surface.Normal.size() != count)
  {
    this->Classify(surface, light, minimumCosine); // for its warning
    return nullptr;
  }
  if (!MakeLightFrame(light).Usable)
  {
    Warn("light has no direction (position equals focal point): every pixel ignored");
    return nullptr;
  }
  return this->Pimpl.get();
}

//------------------------------------------------------------------------------
std::vector<unsigned char> Oracle::CountOccluders(
  const Surface& surface, vtkLight* light, const std::vector<Truth>& truth, int most) const
{
  std::vector<unsigned char> counts(truth.size(), 0);
  const LightFrame frame = light ? MakeLightFrame(light) : LightFrame();
  if (!light || !this->Pimpl || !this->Pimpl->Opaque.Scene || !frame.Usable ||
    truth.size() != surface.Valid.size() || surface.Position.size() != truth.size() ||
    surface.Normal.size() != truth.size())
  {
    return counts;
  }
  const Impl& impl = *this->Pimpl;
  const int capped = std::max(1, std::min(most, 255));
  ForEachRow(surface.Height, [&](int y) {
    for (int x = 0; x < surface.Width; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * surface.Width + x;
      Ray ray;
      if (truth[i] == Truth::Shadowed &&
        impl.ShadowRay(frame, surface.Position[i], surface.Normal[i], -1.0, ray))
      {
        counts[i] = static_cast<unsigned char>(impl.CountGeometries(ray, capped));
      }
    }
  });
  return counts;
}

} // namespace shadoworacle
