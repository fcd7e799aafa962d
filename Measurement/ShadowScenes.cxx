#include "ShadowScenes.h"

#include "vtkAbstractShadowMapPass.h" // LIGHT_SIZE

#include <vtkActorCollection.h>

#include <glm/glm.hpp>
#include <vtkInformation.h>
#include <vtkInformationDoubleKey.h>
#include <vtkMatrix4x4.h>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkAlgorithm.h>
#include <vtkAppendPolyData.h>
#include <vtkCamera.h>
#include <vtkColorTransferFunction.h>
#include <vtkContourFilter.h>
#include <vtkCubeSource.h>
#include <vtkCutter.h>
#include <vtkCylinderSource.h>
#include <vtkDataObject.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkFloatArray.h>
#include <vtkGLTFReader.h>
#include <vtkGradientFilter.h>
#include <vtkLight.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkMath.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPlane.h>
#include <vtkPlaneSource.h>
#include <vtkElevationFilter.h>
#include <vtkLookupTable.h>
#include <vtkPoints.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkPolyDataMapper.h>
#include <vtkInformationVector.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRTAnalyticSource.h>
#include <vtkRenderer.h>
#include <vtkSMPTools.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkStreamTracer.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkTubeFilter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkVolumeProperty.h>
#include <vtkVolumeCollection.h>
#include <vtkVolume.h>
#include <vtkSmartVolumeMapper.h>
#include <vtkPiecewiseFunction.h>
#include <vtkImageData.h>

#include <algorithm>
#include <functional>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <new>
#include <vector>

#if !defined(_WIN32)
#include <cerrno>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace shadowscenes
{
namespace
{

constexpr double AmbientCoefficient = 0.15;

struct Color
{
  double r, g, b;
};

constexpr Color GroundColor{ 0.80, 0.80, 0.78 };
constexpr Color PoleColor{ 0.85, 0.82, 0.70 };
constexpr Color IsosurfaceColor{ 0.86, 0.38, 0.24 };
constexpr Color SphereColor{ 0.30, 0.50, 0.85 };
constexpr Color ModelColor{ 0.75, 0.72, 0.65 };
constexpr Color BackgroundColor{ 0.62, 0.72, 0.85 };
constexpr Color StreamTubeColor{ 0.92, 0.92, 0.88 };

void ApplyMaterial(vtkActor* actor, const Color& color, double specular)
{
  vtkProperty* property = actor->GetProperty();
  // SetColor sets the ambient, diffuse and specular colours at once, so the
  // ambient term takes the object's colour; the highlight is reset to white.
  property->SetColor(color.r, color.g, color.b);
  property->SetAmbient(AmbientCoefficient);
  property->SetDiffuse(1.0);
  property->SetSpecular(specular);
  property->SetSpecularPower(30.0);
  property->SetSpecularColor(1.0, 1.0, 1.0);
}

vtkSmartPointer<vtkActor> AddActorWithMapper(
  vtkRenderer* renderer, vtkPolyDataMapper* mapper, const Color& color, double specular)
{
  mapper->ScalarVisibilityOff(); // one colour per actor, whatever arrays the data carries
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  ApplyMaterial(actor, color, specular);
  renderer->AddActor(actor);
  return actor;
}

vtkSmartPointer<vtkActor> AddActor(
  vtkRenderer* renderer, vtkAlgorithmOutput* port, const Color& color, double specular)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(port);
  return AddActorWithMapper(renderer, mapper, color, specular);
}

vtkSmartPointer<vtkActor> AddActor(
  vtkRenderer* renderer, vtkPolyData* data, const Color& color, double specular)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  return AddActorWithMapper(renderer, mapper, color, specular);
}

/** Square ground plane at height z, normal +z. */
void AddGround(vtkRenderer* renderer, double xMin, double xMax, double yMin, double yMax, double z)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(xMin, yMin, z);
  plane->SetPoint1(xMax, yMin, z);
  plane->SetPoint2(xMin, yMax, z);
  AddActor(renderer, plane->GetOutputPort(), GroundColor, 0.05);
}

/** Unit vector for an azimuth (from +x towards +y) and an elevation above z = 0. */
void DirectionFromAngles(double azimuthDeg, double elevationDeg, double direction[3])
{
  const double azimuth = vtkMath::RadiansFromDegrees(azimuthDeg);
  const double elevation = vtkMath::RadiansFromDegrees(elevationDeg);
  direction[0] = std::cos(elevation) * std::cos(azimuth);
  direction[1] = std::cos(elevation) * std::sin(azimuth);
  direction[2] = std::sin(elevation);
}

void SetCamera(vtkRenderer* renderer, const double position[3], const double focalPoint[3],
  double viewAngleDeg)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(position[0], position[1], position[2]);
  camera->SetFocalPoint(focalPoint[0], focalPoint[1], focalPoint[2]);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(viewAngleDeg);
  camera->OrthogonalizeViewUp();
  renderer->ResetCameraClippingRange();
}

// --- default scene ---------------------------------------------------------

void AddPoles(vtkRenderer* renderer)
{
  constexpr int poleCount = 8;
  constexpr double poleHeight = 10.0;
  constexpr double poleSpacing = 10.0;
  constexpr double poleY = 6.0;
  constexpr double firstPoleX = 20.0;

  vtkNew<vtkCylinderSource> cylinder; // axis along y, centred at the origin
  cylinder->SetRadius(0.25);
  cylinder->SetHeight(poleHeight);
  cylinder->SetResolution(24);

  for (int i = 0; i < poleCount; ++i)
  {
    vtkSmartPointer<vtkActor> pole =
      AddActor(renderer, cylinder->GetOutputPort(), PoleColor, 0.3);
    pole->SetOrientation(90.0, 0.0, 0.0); // y axis -> z axis
    pole->SetPosition(firstPoleX - i * poleSpacing, poleY, 0.5 * poleHeight);
  }
}

void AddIsosurface(vtkRenderer* renderer)
{
  constexpr double scale = 0.3; // the wavelet's 20-unit box becomes 6 units
  constexpr double centerX = 16.0;
  constexpr double centerY = -10.0;

  vtkNew<vtkRTAnalyticSource> wavelet; // default extent [-10, 10]^3
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(wavelet->GetOutputPort());
  // ParaView's default: the middle of the wavelet's scalar range [37.4, 276.8].
  contour->SetValue(0, 157.09);
  contour->Update();

  double bounds[6];
  contour->GetOutput()->GetBounds(bounds);
  vtkSmartPointer<vtkActor> isosurface =
    AddActor(renderer, contour->GetOutputPort(), IsosurfaceColor, 0.4);
  isosurface->SetScale(scale);
  isosurface->SetPosition(centerX - scale * 0.5 * (bounds[0] + bounds[1]),
    centerY - scale * 0.5 * (bounds[2] + bounds[3]), -scale * bounds[4]);
}

void AddSphere(vtkRenderer* renderer)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-8.0, -2.0, 4.5); // floats 2 units above the ground
  sphere->SetRadius(2.5);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  AddActor(renderer, sphere->GetOutputPort(), SphereColor, 0.5);
}

// --- file scene --------------------------------------------------------------

/** Turns off VTK's error and warning output for its lifetime. */
class ScopedVTKMessagesOff
{
public:
  ScopedVTKMessagesOff()
    : WasOn(vtkObject::GetGlobalWarningDisplay() != 0)
  {
    vtkObject::GlobalWarningDisplayOff();
  }
  ~ScopedVTKMessagesOff() { vtkObject::SetGlobalWarningDisplay(this->WasOn ? 1 : 0); }
  ScopedVTKMessagesOff(const ScopedVTKMessagesOff&) = delete;
  ScopedVTKMessagesOff& operator=(const ScopedVTKMessagesOff&) = delete;

private:
  bool WasOn;
};

std::string LowerCaseExtension(const std::string& path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

bool IsSupportedModelExtension(const std::string& extension)
{
  for (const char* supported : { ".obj", ".ply", ".stl", ".vtp", ".gltf", ".glb" })
  {
    if (extension == supported)
    {
      return true;
    }
  }
  return false;
}

/** All non-empty polydata leaves of a composite dataset, appended into one. */
vtkSmartPointer<vtkPolyData> AppendPolyDataLeaves(vtkMultiBlockDataSet* blocks)
{
  if (!blocks)
  {
    return nullptr;
  }
  vtkNew<vtkAppendPolyData> append;
  auto leaves = vtkSmartPointer<vtkDataObjectTreeIterator>::Take(blocks->NewTreeIterator());
  leaves->VisitOnlyLeavesOn();
  leaves->TraverseSubTreeOn();
  for (leaves->InitTraversal(); !leaves->IsDoneWithTraversal(); leaves->GoToNextItem())
  {
    vtkPolyData* leaf = vtkPolyData::SafeDownCast(leaves->GetCurrentDataObject());
    if (leaf && leaf->GetNumberOfPoints() > 0)
    {
      append->AddInputData(leaf);
    }
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    return nullptr;
  }
  append->Update();
  return append->GetOutput();
}

template <typename Reader>
vtkSmartPointer<vtkPolyData> ReadWith(const std::string& path)
{
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

bool HasGeometry(vtkPolyData* model)
{
  return model && model->GetNumberOfPoints() > 0 && model->GetNumberOfCells() > 0;
}

/** Point ids within the points and finite coordinates: safe to render and frame. */
bool IsWellFormed(vtkPolyData* model)
{
  const double numberOfPoints = static_cast<double>(model->GetNumberOfPoints());
  for (vtkCellArray* cells :
    { model->GetVerts(), model->GetLines(), model->GetPolys(), model->GetStrips() })
  {
    vtkDataArray* pointIds = cells ? cells->GetConnectivityArray() : nullptr;
    if (pointIds && pointIds->GetNumberOfValues() > 0)
    {
      double range[2];
      pointIds->GetRange(range);
      if (range[0] < 0.0 || range[1] >= numberOfPoints)
      {
        return false;
      }
    }
  }
  double bounds[6];
  model->GetBounds(bounds);
  return std::all_of(bounds, bounds + 6, [](double b) { return std::isfinite(b); });
}

/** Reads the model in this process; null or empty on failure. */
vtkSmartPointer<vtkPolyData> ReadModel(const std::string& path, const std::string& extension)
{
  ScopedVTKMessagesOff quiet;
  if (extension == ".obj")
  {
    return ReadWith<vtkOBJReader>(path);
  }
  if (extension == ".ply")
  {
    return ReadWith<vtkPLYReader>(path);
  }
  if (extension == ".stl")
  {
    return ReadWith<vtkSTLReader>(path);
  }
  if (extension == ".vtp")
  {
    return ReadWith<vtkXMLPolyDataReader>(path);
  }
  vtkNew<vtkGLTFReader> reader; // .gltf and .glb
  reader->SetFileName(path.c_str());
  reader->Update();
  return AppendPolyDataLeaves(vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput()));
}

/**
 * Points, cells and point normals only: readers attach arrays that can be
 * inconsistent with the cells (vtkOBJReader's MaterialIds on line-only
 * files), and the scene colours every model uniformly anyway.
 */
vtkSmartPointer<vtkPolyData> GeometryOnly(vtkPolyData* model)
{
  vtkNew<vtkPolyData> geometry;
  geometry->SetPoints(model->GetPoints());
  geometry->SetVerts(model->GetVerts());
  geometry->SetLines(model->GetLines());
  geometry->SetPolys(model->GetPolys());
  geometry->SetStrips(model->GetStrips());
  vtkDataArray* normals = model->GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 &&
    normals->GetNumberOfTuples() == model->GetNumberOfPoints())
  {
    geometry->GetPointData()->SetNormals(normals);
  }
  return geometry;
}

/** Why a read failed, as the end of a one-line message. */
enum class ReadFailure
{
  None,
  NoGeometry,
  Malformed,
  ReaderFailed,  // threw, e.g. std::bad_alloc on an unsupported compressed glTF
  ReaderCrashed, // died on a signal
};

std::string Describe(ReadFailure failure)
{
  switch (failure)
  {
    case ReadFailure::NoGeometry:
      return "no geometry found";
    case ReadFailure::Malformed:
      return "malformed geometry (point ids out of range or non-finite points)";
    case ReadFailure::ReaderFailed:
      return "the reader failed (malformed or unsupported file?)";
    case ReadFailure::ReaderCrashed:
      return "the reader crashed (malformed file?)";
    case ReadFailure::None:
    default:
      return "";
  }
}

vtkSmartPointer<vtkPolyData> ReadModelInProcess(
  const std::string& path, const std::string& extension, ReadFailure& failure)
{
  try
  {
    vtkSmartPointer<vtkPolyData> model = ReadModel(path, extension);
    failure = !HasGeometry(model) ? ReadFailure::NoGeometry
      : !IsWellFormed(model)      ? ReadFailure::Malformed
                                  : ReadFailure::None;
    return failure == ReadFailure::None ? GeometryOnly(model) : nullptr;
  }
  catch (const std::exception&)
  {
    failure = ReadFailure::ReaderFailed;
    return nullptr;
  }
}

#if defined(_WIN32)

vtkSmartPointer<vtkPolyData> ReadModelIsolated(
  const std::string& path, const std::string& extension, ReadFailure& failure)
{
  return ReadModelInProcess(path, extension, failure);
}

#else

bool WriteAll(int fd, const std::string& data)
{
  std::size_t written = 0;
  while (written < data.size())
  {
    const ssize_t n = ::write(fd, data.data() + written, data.size() - written);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      return false;
    }
    written += static_cast<std::size_t>(n);
  }
  return true;
}

std::string ReadAll(int fd)
{
  std::string data;
  char buffer[1 << 16];
  for (;;)
  {
    const ssize_t n = ::read(fd, buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      return data;
    }
    data.append(buffer, static_cast<std::size_t>(n));
  }
}

/** Child side: read, send the model as VTP down the pipe, exit with a ReadFailure. */
[[noreturn]] void ReadModelInChild(const std::string& path, const std::string& extension, int fd)
{
  // Only this thread survives fork(); keep any SMP code in the readers off
  // the parent's thread pool.
  vtkSMPTools::SetBackend("Sequential");
  ReadFailure failure = ReadFailure::None;
  try
  {
    vtkSmartPointer<vtkPolyData> model = ReadModelInProcess(path, extension, failure);
    if (failure == ReadFailure::None)
    {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetInputData(model);
      writer->WriteToOutputStringOn();
      writer->SetDataModeToAppended();
      writer->EncodeAppendedDataOff();
      writer->SetCompressorTypeToNone();
      writer->Write();
      if (!WriteAll(fd, writer->GetOutputString()))
      {
        failure = ReadFailure::ReaderFailed;
      }
    }
  }
  catch (...)
  {
    failure = ReadFailure::ReaderFailed;
  }
  // _exit: no atexit handlers, no flushing of the parent's buffers, no X calls.
  ::_exit(static_cast<int>(failure));
}

/**
 * Reads the model in a child process: VTK 9.1's readers crash on some
 * malformed files (vtkGLTFReader on out-of-range indices, a missing .bin,
 * recursive nodes...), and a bad file must not take the program down. The
 * child sends the geometry back as VTP through a pipe.
 */
vtkSmartPointer<vtkPolyData> ReadModelIsolated(
  const std::string& path, const std::string& extension, ReadFailure& failure)
{
  int fds[2];
  if (::pipe(fds) != 0)
  {
    return ReadModelInProcess(path, extension, failure);
  }
  const pid_t child = ::fork();
  if (child < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    return ReadModelInProcess(path, extension, failure);
  }
  if (child == 0)
  {
    ::close(fds[0]);
    ReadModelInChild(path, extension, fds[1]);
  }
  ::close(fds[1]);
  const std::string vtp = ReadAll(fds[0]); // until the child exits
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR)
  {
  }
  if (WIFSIGNALED(status))
  {
    failure = ReadFailure::ReaderCrashed;
    return nullptr;
  }
  const int exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (exitCode != static_cast<int>(ReadFailure::None))
  {
    const bool known = exitCode == static_cast<int>(ReadFailure::NoGeometry) ||
      exitCode == static_cast<int>(ReadFailure::Malformed);
    failure = known ? static_cast<ReadFailure>(exitCode) : ReadFailure::ReaderFailed;
    return nullptr;
  }

  ScopedVTKMessagesOff quiet;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->ReadFromInputStringOn();
  reader->SetInputString(vtp);
  reader->Update();
  vtkSmartPointer<vtkPolyData> model = reader->GetOutput();
  failure = HasGeometry(model) && IsWellFormed(model) ? ReadFailure::None
                                                      : ReadFailure::ReaderFailed;
  return model;
}

#endif

/** The model turned so that its up axis is +z (its normals with it). */
vtkSmartPointer<vtkPolyData> TurnedUp(vtkPolyData* model, UpAxis up)
{
  if (up == UpAxis::PlusZ || up == UpAxis::Auto)
  {
    return model;
  }
  const std::array<double, 9> rotation = RotationToZUp(up);
  vtkNew<vtkMatrix4x4> matrix;
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      matrix->SetElement(row, column, rotation[3 * row + column]);
    }
  }
  vtkNew<vtkTransform> transform;
  transform->SetMatrix(matrix);
  vtkNew<vtkTransformPolyDataFilter> turn;
  turn->SetTransform(transform);
  turn->SetInputData(model);
  turn->Update();
  return turn->GetOutput();
}

/** Smooth normals for models that come without them (STL, many PLY files). */
vtkSmartPointer<vtkPolyData> WithNormals(vtkPolyData* model)
{
  if (model->GetPointData()->GetNormals() || model->GetNumberOfPolys() == 0)
  {
    return model;
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(model);
  normals->SetFeatureAngle(60.0);
  normals->Update();
  return normals->GetOutput();
}

bool IsReadableFile(const std::string& path)
{
  std::error_code ignored;
  if (!std::filesystem::is_regular_file(path, ignored))
  {
    return false;
  }
  std::ifstream file(path, std::ios::binary);
  return file.good();
}

void FrameModel(vtkRenderer* renderer, const double bounds[6])
{
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double dx = bounds[1] - bounds[0];
  const double dy = bounds[3] - bounds[2];
  const double dz = bounds[5] - bounds[4];
  const double halfDiagonal = std::max(0.5 * std::sqrt(dx * dx + dy * dy + dz * dz), 1e-6);

  constexpr double viewAngleDeg = 30.0;
  // Distance at which the bounding sphere fills the view, with some margin.
  const double distance =
    1.15 * halfDiagonal / std::sin(vtkMath::RadiansFromDegrees(0.5 * viewAngleDeg));
  double direction[3];
  // From about the side the default scene is seen from (+x, slightly -y), so
  // that the default sun (azimuth 60) lights the visible side.
  DirectionFromAngles(-15.0, 30.0, direction);
  const double position[3] = { center[0] + distance * direction[0],
    center[1] + distance * direction[1], center[2] + distance * direction[2] };
  SetCamera(renderer, position, center, viewAngleDeg);
}

struct SceneSphere
{
  double center[3] = { 0.0, 0.0, 0.0 };
  double radius = 1.0;
};

SceneSphere VisibleSceneSphere(vtkRenderer* renderer)
{
  SceneSphere sphere;
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    return sphere;
  }
  double diagonal2 = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    sphere.center[axis] = 0.5 * (bounds[2 * axis] + bounds[2 * axis + 1]);
    const double extent = bounds[2 * axis + 1] - bounds[2 * axis];
    diagonal2 += extent * extent;
  }
  sphere.radius = std::max(0.5 * std::sqrt(diagonal2), 1e-6);
  return sphere;
}

// --- benchmark scenes: camera --------------------------------------------------

// The camera path (SetCameraPathFrame): forward by this fraction of the
// initial focal distance over the whole path.
constexpr double CameraPathDollyFraction = 0.2;

/**
 * Widens a camera's clipping range, as set by ResetCameraClippingRange, so
 * that what it holds from the initial camera stays in it along the whole
 * camera path, which brings the camera closer and turns it.
 */
void HoldClippingRangeAlongCameraPath(vtkCamera* camera)
{
  double range[2];
  camera->GetClippingRange(range);
  const double dolly = CameraPathDollyFraction * camera->GetDistance();
  const double nearPlane = std::max(range[0] - 1.5 * dolly, 0.01 * range[1]);
  camera->SetClippingRange(std::min(nearPlane, range[0]), range[1] + dolly);
}

/** Rotates a vector about the +z axis. */
void RotateAboutZ(double vector[3], double angleRad)
{
  const double c = std::cos(angleRad);
  const double s = std::sin(angleRad);
  const double x = vector[0];
  vector[0] = c * x - s * vector[1];
  vector[1] = s * x + c * vector[1];
}

// --- outdoor scene ---------------------------------------------------------------

constexpr double OutdoorHalfSide = 200.0; // the ground is 400 x 400
constexpr double PoleSpacing = 4.0;
constexpr double PoleJitter = 0.8; // at most, along x and along y
constexpr double PoleRadius = 0.12;
constexpr double PoleMinHeight = 3.0;
constexpr double PoleMaxHeight = 5.0;
constexpr int PoleSides = 8;
// The pole columns next to x = 0 stand at x = -2 and x = 2 before jitter,
// which leaves |x| < 1.08 free: the camera stands in that aisle, looks down
// it along +y, and the camera path moves it along it.
constexpr double OutdoorCameraPosition[3] = { 0.0, -170.0, 2.0 };
constexpr double OutdoorFocalDistance = 20.0;
constexpr double OutdoorViewAngleDeg = 30.0;
constexpr double OutdoorNearPlane = 0.2;
constexpr double OutdoorFarPlane = 300.0;

struct Ball
{
  double center[3];
  double radius;
};

/**
 * Near the camera: one resting on the ground, one floating, one resting in
 * the aisle 30 units ahead (past the camera path's end); then three far ones.
 */
const std::vector<Ball>& OutdoorBalls()
{
  static const std::vector<Ball> balls = {
    { { 3.0, -160.0, 0.9 }, 0.9 },
    { { -2.6, -152.0, 2.3 }, 0.7 },
    { { 0.0, -140.0, 1.2 }, 1.2 },
    { { 12.0, -90.0, 4.0 }, 4.0 },
    { { -25.0, -20.0, 9.0 }, 6.0 },
    { { 40.0, 60.0, 8.0 }, 8.0 },
  };
  return balls;
}

/** Deterministic value in [0, 1) for a grid cell and a channel (MurmurHash3's finaliser). */
double CellNoise(int i, int j, int channel)
{
  std::uint32_t h = static_cast<std::uint32_t>(i) * 0x9E3779B1u;
  h ^= static_cast<std::uint32_t>(j) * 0x85EBCA77u;
  h ^= static_cast<std::uint32_t>(channel) * 0xC2B2AE3Du;
  h ^= h >> 16;
  h *= 0x85EBCA6Bu;
  h ^= h >> 13;
  h *= 0xC2B2AE35u;
  h ^= h >> 16;
  return h / 4294967296.0;
}

struct Pole
{
  double x, y, height;
};

bool TouchesBall(double x, double y, const std::vector<Ball>& balls)
{
  constexpr double clearance = 0.3;
  return std::any_of(balls.begin(), balls.end(), [&](const Ball& ball) {
    return std::hypot(x - ball.center[0], y - ball.center[1]) <
      ball.radius + PoleRadius + clearance;
  });
}

/** A jittered grid over the whole ground, less the poles that would touch a ball. */
std::vector<Pole> PlacePoles(const std::vector<Ball>& balls)
{
  const int perSide = static_cast<int>(2.0 * OutdoorHalfSide / PoleSpacing);
  const double first = -OutdoorHalfSide + 0.5 * PoleSpacing;
  std::vector<Pole> poles;
  poles.reserve(static_cast<std::size_t>(perSide) * perSide);
  for (int j = 0; j < perSide; ++j)
  {
    for (int i = 0; i < perSide; ++i)
    {
      const double x = first + i * PoleSpacing + PoleJitter * (2.0 * CellNoise(i, j, 0) - 1.0);
      const double y = first + j * PoleSpacing + PoleJitter * (2.0 * CellNoise(i, j, 1) - 1.0);
      const double height =
        PoleMinHeight + (PoleMaxHeight - PoleMinHeight) * CellNoise(i, j, 2);
      if (!TouchesBall(x, y, balls))
      {
        poles.push_back({ x, y, height });
      }
    }
  }
  return poles;
}

/**
 * All poles in one polydata: per pole, the sides of an upright prism with
 * radial normals and a top cap (no bottom: it stands on the ground), as
 * counter-clockwise triangles, 3 * PoleSides - 2 of them.
 */
vtkSmartPointer<vtkPolyData> MakePoles(const std::vector<Pole>& poles)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> triangles;
  for (const Pole& pole : poles)
  {
    // Per side k: bottom, top, top-cap points at ids first + 3k, +1, +2.
    const vtkIdType first = points->GetNumberOfPoints();
    for (int k = 0; k < PoleSides; ++k)
    {
      const double angle = 2.0 * vtkMath::Pi() * k / PoleSides;
      const double c = std::cos(angle);
      const double s = std::sin(angle);
      const double x = pole.x + PoleRadius * c;
      const double y = pole.y + PoleRadius * s;
      points->InsertNextPoint(x, y, 0.0);
      points->InsertNextPoint(x, y, pole.height);
      points->InsertNextPoint(x, y, pole.height);
      normals->InsertNextTuple3(c, s, 0.0);
      normals->InsertNextTuple3(c, s, 0.0);
      normals->InsertNextTuple3(0.0, 0.0, 1.0);
    }
    for (int k = 0; k < PoleSides; ++k)
    {
      const vtkIdType a = first + 3 * k;
      const vtkIdType b = first + 3 * ((k + 1) % PoleSides);
      triangles->InsertNextCell({ a, b, b + 1 });
      triangles->InsertNextCell({ a, b + 1, a + 1 });
    }
    for (int k = 1; k + 1 < PoleSides; ++k)
    {
      triangles->InsertNextCell({ first + 2, first + 3 * k + 2, first + 3 * (k + 1) + 2 });
    }
  }
  vtkNew<vtkPolyData> polesData;
  polesData->SetPoints(points);
  polesData->SetPolys(triangles);
  polesData->GetPointData()->SetNormals(normals);
  return polesData;
}

vtkSmartPointer<vtkPolyData> MakeBalls(const std::vector<Ball>& balls)
{
  vtkNew<vtkAppendPolyData> append;
  for (const Ball& ball : balls)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(ball.center[0], ball.center[1], ball.center[2]);
    sphere->SetRadius(ball.radius);
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(24);
    sphere->Update();
    append->AddInputData(sphere->GetOutput());
  }
  append->Update();
  return append->GetOutput();
}

// --- ParaView scene ----------------------------------------------------------------

// vtkRTAnalyticSource's default box is [-10, 10]^3, its scalars span [37.4, 276.8].
constexpr double WaveletScalarRange[2] = { 37.35, 276.83 };
constexpr double WaveletIsoValue = 215.0; // a two-lobed blob around the maximum
constexpr double WaveletSliceY = 4.0;     // vertical slice behind the blob's centre
constexpr double StreamSeedRadius = 9.0;  // seeds on a sphere inside the box
constexpr double StreamTubeRadius = 0.2;
constexpr double ParaViewGroundZ = -15.0;        // 5 units below the box
constexpr double ParaViewGroundHalfSide = 200.0; // fills the view up to its top edge
constexpr double ParaViewFocalPoint[3] = { 0.0, 0.0, -3.0 };
constexpr double ParaViewCameraDistance = 60.0;
constexpr double ParaViewCameraAzimuthDeg = -56.0;
constexpr double ParaViewCameraElevationDeg = 32.0;

vtkSmartPointer<vtkPolyData> WaveletIsosurface(vtkAlgorithmOutput* wavelet)
{
  vtkNew<vtkContourFilter> contour; // with normals, from the image gradient
  contour->SetInputConnection(wavelet);
  contour->SetValue(0, WaveletIsoValue);
  contour->Update();
  return contour->GetOutput();
}

vtkSmartPointer<vtkPolyData> WaveletSlice(vtkAlgorithmOutput* wavelet)
{
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.0, WaveletSliceY, 0.0);
  plane->SetNormal(0.0, 1.0, 0.0);
  vtkNew<vtkCutter> cutter; // keeps the interpolated RTData scalars
  cutter->SetInputConnection(wavelet);
  cutter->SetCutFunction(plane);
  cutter->Update();
  return cutter->GetOutput();
}

/**
 * Tubes along streamlines of the wavelet's gradient (it has no vectors of its
 * own), seeded at the points of a coarse sphere and traced both ways: they
 * run in towards the maximum and out to the box's faces.
 */
vtkSmartPointer<vtkPolyData> GradientStreamTubes(vtkAlgorithmOutput* wavelet)
{
  vtkNew<vtkGradientFilter> gradient;
  gradient->SetInputConnection(wavelet);
  gradient->SetInputScalars(vtkDataObject::FIELD_ASSOCIATION_POINTS, "RTData");
  gradient->SetResultArrayName("Gradient");

  vtkNew<vtkSphereSource> seeds; // 34 points
  seeds->SetRadius(StreamSeedRadius);
  seeds->SetThetaResolution(8);
  seeds->SetPhiResolution(6);

  vtkNew<vtkStreamTracer> tracer;
  tracer->SetInputConnection(gradient->GetOutputPort());
  tracer->SetSourceConnection(seeds->GetOutputPort());
  tracer->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Gradient");
  tracer->SetIntegratorTypeToRungeKutta45();
  tracer->SetIntegrationDirectionToBoth();
  tracer->SetMaximumPropagation(60.0);
  tracer->SetMaximumNumberOfSteps(400);
  tracer->SetTerminalSpeed(1.0); // stop at the maximum instead of circling it

  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputConnection(tracer->GetOutputPort());
  tubes->SetRadius(StreamTubeRadius);
  tubes->SetNumberOfSides(8);
  tubes->CappingOn();
  tubes->Update();
  return tubes->GetOutput();
}

/** Colours by the point scalars with ParaView's "Cool to Warm" map. */
void AddColorMappedActor(vtkRenderer* renderer, vtkPolyData* data, const double range[2])
{
  vtkNew<vtkColorTransferFunction> coolToWarm;
  coolToWarm->SetColorSpaceToDiverging();
  coolToWarm->AddRGBPoint(range[0], 0.230, 0.299, 0.754);
  coolToWarm->AddRGBPoint(range[1], 0.706, 0.016, 0.150);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->SetLookupTable(coolToWarm);
  mapper->SetScalarRange(range[0], range[1]);
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  ApplyMaterial(actor, Color{ 1.0, 1.0, 1.0 }, 0.1); // the scalars give the colour
  renderer->AddActor(actor);
}

// --- light set-ups -------------------------------------------------------------------

/** The active camera seen from above. */
struct ViewFrame
{
  double focalPoint[3];
  double position[3]; // the camera's
  double forward[3]; // the view direction projected onto the ground, unit length
  double left[3];    // forward turned 90 degrees counter-clockwise about +z
  double distance;   // from the camera to its focal point
};

ViewFrame ViewFrameOf(vtkCamera* camera)
{
  ViewFrame view;
  camera->GetFocalPoint(view.focalPoint);
  camera->GetPosition(view.position);
  view.distance = camera->GetDistance();
  double direction[3];
  camera->GetDirectionOfProjection(direction);
  if (std::hypot(direction[0], direction[1]) < 1e-6)
  {
    camera->GetViewUp(direction); // looking straight down: "forward" is up the screen
  }
  double horizontal = std::hypot(direction[0], direction[1]);
  if (horizontal < 1e-6)
  {
    direction[0] = 0.0;
    direction[1] = 1.0;
    horizontal = 1.0;
  }
  view.forward[0] = direction[0] / horizontal;
  view.forward[1] = direction[1] / horizontal;
  view.forward[2] = 0.0;
  view.left[0] = -view.forward[1];
  view.left[1] = view.forward[0];
  view.left[2] = 0.0;
  return view;
}

/**
 * The point `ahead`, `left` and `up` view distances from `origin` (the focal
 * point or the camera), along the view frame's forward, left and +z.
 */
void PointFrom(const ViewFrame& view, const double origin[3], double ahead, double left,
  double up, double point[3])
{
  for (int axis = 0; axis < 3; ++axis)
  {
    point[axis] = origin[axis] + view.distance * (ahead * view.forward[axis] + left * view.left[axis]);
  }
  point[2] += view.distance * up;
}

void PointFromFocus(const ViewFrame& view, double ahead, double left, double up, double point[3])
{
  PointFrom(view, view.focalPoint, ahead, left, up, point);
}

/** A sun with its azimuth counter-clockwise from the view's forward direction. */
struct SunSetup
{
  const char* name;
  double azimuthDeg;
  double elevationDeg;
};

constexpr double SunElevationDeg = 35.0;
constexpr double OverheadTiltDeg = 4.0;
// Exactly behind, the shadows hide behind their casters when the camera looks
// down about as steeply as the sun shines (the model and ParaView scenes).
constexpr double BehindSideDeg = 25.0;
constexpr SunSetup SunSetups[] = {
  { "overhead", 135.0, 90.0 - OverheadTiltDeg },
  { "perpendicular", -90.0, SunElevationDeg },
  { "behind", 180.0 - BehindSideDeg, SunElevationDeg },
  { "facing", 0.0, SunElevationDeg },
};
constexpr double SpotConeAngleDeg = 45.0; // vtkLight's cone angle is the half-angle
constexpr double WideSpotConeAngleDeg = 75.0;
constexpr double SoftSunDiameterDeg = 0.53; // the sun's, seen from the earth
constexpr double SoftLampRadiusFraction = 0.02; // of the camera's distance to its focal point

/** A white directional scene light shining from `position` towards `focalPoint`. */
vtkSmartPointer<vtkLight> MakeSceneLight(const double position[3], const double focalPoint[3])
{
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetColor(1.0, 1.0, 1.0);
  light->SetIntensity(1.0);
  light->SetPositional(false);
  light->SetPosition(position[0], position[1], position[2]);
  light->SetFocalPoint(focalPoint[0], focalPoint[1], focalPoint[2]);
  return light;
}

/** A spot light, or a point light for a cone angle of 180 degrees. */
vtkSmartPointer<vtkLight> MakePositionalLight(
  const double position[3], const double focalPoint[3], double coneAngleDeg)
{
  vtkSmartPointer<vtkLight> light = MakeSceneLight(position, focalPoint);
  light->SetPositional(true);
  light->SetConeAngle(coneAngleDeg);
  return light;
}

vtkSmartPointer<vtkLight> MakeSun(const ViewFrame& view, const SunSetup& sun)
{
  const double azimuth = vtkMath::RadiansFromDegrees(sun.azimuthDeg);
  const double elevation = vtkMath::RadiansFromDegrees(sun.elevationDeg);
  const double ahead = std::cos(elevation) * std::cos(azimuth);
  const double left = std::cos(elevation) * std::sin(azimuth);
  double position[3]; // only the direction to the focal point matters
  PointFromFocus(view, ahead, left, std::sin(elevation), position);
  return MakeSceneLight(position, view.focalPoint);
}

vtkSmartPointer<vtkLight> MakeSetupLight(const ViewFrame& view, const std::string& setup);

// The number N of a sized set-up named `kind` + "-N" ("soft-sun-2"), if N is in
// (0, largest]; otherwise 0.
double SizedSetupNumber(const std::string& setup, const std::string& kind, double largest)
{
  const std::string prefix = kind + "-";
  if (setup.compare(0, prefix.size(), prefix) != 0)
  {
    return 0.0;
  }
  const std::string number = setup.substr(prefix.size());
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  const bool parsed = !number.empty() && end == number.c_str() + number.size();
  return parsed && value > 0.0 && value <= largest ? value : 0.0;
}

// "soft-sun-D": the sun D degrees across; "soft-spot-P", "soft-point-P": the
// lamp's radius P% of the camera's distance to its focal point.
constexpr double WidestSunDeg = 30.0;
constexpr double LargestLampPercent = 25.0; // the point lamp is 0.5 d above the focus

double WiderSunDiameter(const std::string& setup)
{
  return SizedSetupNumber(setup, "soft-sun", WidestSunDeg);
}

// True for `lamp` ("soft-spot", "soft-point") and its "-P" sizes.
bool IsSizedLampSetup(const std::string& setup, const std::string& lamp)
{
  return setup == lamp || SizedSetupNumber(setup, lamp, LargestLampPercent) > 0.0;
}

double LargerLampPercent(const std::string& setup)
{
  return std::max(SizedSetupNumber(setup, "soft-spot", LargestLampPercent),
    SizedSetupNumber(setup, "soft-point", LargestLampPercent));
}

// A sized set-up is its hard set-up's light with a size (LIGHT_SIZE).
vtkSmartPointer<vtkLight> MakeSizedSetupLight(const ViewFrame& view, const std::string& setup)
{
  const std::string kind = LightKindOfSetup(setup);
  vtkSmartPointer<vtkLight> light = MakeSetupLight(view, kind == "sun" ? "perpendicular" : kind);
  const double wider = WiderSunDiameter(setup);
  const double larger = LargerLampPercent(setup);
  light->GetInformation()->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), kind == "sun"
      ? (wider > 0.0 ? wider : SoftSunDiameterDeg)
      : (larger > 0.0 ? 0.01 * larger : SoftLampRadiusFraction) * view.distance);
  return light;
}

vtkSmartPointer<vtkLight> MakeSetupLight(const ViewFrame& view, const std::string& setup)
{
  if (IsSizedLightSetup(setup))
  {
    return MakeSizedSetupLight(view, setup);
  }
  double position[3];
  if (setup == "spot")
  {
    PointFromFocus(view, -0.6, 0.0, 0.8, position);
    return MakePositionalLight(position, view.focalPoint, SpotConeAngleDeg);
  }
  if (setup == "wide-spot")
  {
    PointFromFocus(view, -0.6, 0.0, 0.8, position);
    return MakePositionalLight(position, view.focalPoint, WideSpotConeAngleDeg);
  }
  if (setup == "point" || setup == "street-point" || setup == "lamp-behind")
  {
    if (setup == "point")
    {
      PointFromFocus(view, -0.3, 0.0, 0.5, position);
    }
    else if (setup == "street-point")
    {
      PointFromFocus(view, -0.75, 0.1, 0.08, position);
    }
    else
    {
      PointFrom(view, view.position, -0.05, 0.0, 0.8, position);
    }
    const double below[3] = { position[0], position[1], position[2] - 1.0 };
    return MakePositionalLight(position, below, 180.0);
  }
  const auto sun = std::find_if(std::begin(SunSetups), std::end(SunSetups),
    [&](const SunSetup& candidate) { return setup == candidate.name; });
  return MakeSun(view, *sun);
}


// --- the sweep's procedural scenes --------------------------------------------------

constexpr Color BuildingColor{ 0.78, 0.74, 0.70 };
constexpr Color WallColor{ 0.85, 0.83, 0.78 };
constexpr Color FurnitureColor{ 0.55, 0.40, 0.28 };

/** An axis-aligned box as six quads with outward normals. */
vtkSmartPointer<vtkPolyData> MakeBox(const double bounds[6])
{
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]);
  cube->Update();
  return cube->GetOutput();
}

/** Boxes (xmin, xmax, ymin, ymax, zmin, zmax each) in one polydata. */
vtkSmartPointer<vtkPolyData> MakeBoxes(const std::vector<std::array<double, 6>>& boxes)
{
  vtkNew<vtkAppendPolyData> append;
  for (const auto& box : boxes)
  {
    append->AddInputData(MakeBox(box.data()));
  }
  append->Update();
  return append->GetOutput();
}

/** A cylinder of `radius` from `base` along the unit `axis` for `length`. */
vtkSmartPointer<vtkPolyData> MakeRod(
  const double base[3], const double axis[3], double length, double radius)
{
  vtkNew<vtkCylinderSource> cylinder; // along y, centred at the origin
  cylinder->SetRadius(radius);
  cylinder->SetHeight(length);
  cylinder->SetResolution(8);
  // Rotate y onto the axis (about y x axis), then move the centre into place.
  const double y[3] = { 0.0, 1.0, 0.0 };
  double about[3];
  vtkMath::Cross(y, axis, about);
  const double angle = vtkMath::DegreesFromRadians(
    std::atan2(vtkMath::Norm(about), vtkMath::Dot(y, axis)));
  vtkNew<vtkTransform> transform;
  transform->Translate(base[0] + 0.5 * length * axis[0], base[1] + 0.5 * length * axis[1],
    base[2] + 0.5 * length * axis[2]);
  if (vtkMath::Norm(about) > 1e-9)
  {
    transform->RotateWXYZ(angle, about);
  }
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetInputConnection(cylinder->GetOutputPort());
  place->SetTransform(transform);
  place->Update();
  return place->GetOutput();
}

std::vector<std::array<double, 6>> CityBuildings(const CityLayout& city)
{
  std::vector<std::array<double, 6>> buildings;
  const double block = city.Pitch - city.StreetWidth;
  for (int j = 0; j < city.Blocks; ++j)
  {
    for (int i = 0; i < city.Blocks; ++i)
    {
      const double x = city.StreetCenter(i) + 0.5 * city.StreetWidth;
      const double y = city.StreetCenter(j) + 0.5 * city.StreetWidth;
      const double height = 6.0 + 34.0 * CellNoise(i, j, 7);
      // Some blocks hold two buildings of different heights.
      if (CellNoise(i, j, 8) < 0.4)
      {
        const double lower = 0.4 * height;
        buildings.push_back({ x, x + 0.5 * block, y, y + block, 0.0, height });
        buildings.push_back({ x + 0.5 * block, x + block, y, y + block, 0.0, lower });
      }
      else
      {
        buildings.push_back({ x, x + block, y, y + block, 0.0, height });
      }
    }
  }
  return buildings;
}

constexpr double FieldHalfSide = 30.0;
constexpr int FieldRods = 240;
constexpr int FieldBoards = 40;

/** Thin rods leaning up to 40 degrees and thin boards, scattered by CellNoise. */
vtkSmartPointer<vtkPolyData> MakeThinCasters()
{
  vtkNew<vtkAppendPolyData> append;
  for (int k = 0; k < FieldRods; ++k)
  {
    const double base[3] = { FieldHalfSide * (2.0 * CellNoise(k, 0, 11) - 1.0),
      FieldHalfSide * (2.0 * CellNoise(k, 0, 12) - 1.0), 0.0 };
    const double tilt = vtkMath::RadiansFromDegrees(40.0 * CellNoise(k, 0, 13));
    const double heading = 2.0 * vtkMath::Pi() * CellNoise(k, 0, 14);
    const double axis[3] = { std::sin(tilt) * std::cos(heading), std::sin(tilt) * std::sin(heading),
      std::cos(tilt) };
    const double length = 2.0 + 6.0 * CellNoise(k, 0, 15);
    const double radius = 0.03 + 0.09 * CellNoise(k, 0, 16);
    append->AddInputData(MakeRod(base, axis, length, radius));
  }
  std::vector<std::array<double, 6>> boards;
  for (int k = 0; k < FieldBoards; ++k)
  {
    const double x = FieldHalfSide * (2.0 * CellNoise(k, 1, 11) - 1.0);
    const double y = FieldHalfSide * (2.0 * CellNoise(k, 1, 12) - 1.0);
    const double z = 0.5 + 4.0 * CellNoise(k, 1, 13);
    const bool alongX = CellNoise(k, 1, 14) < 0.5;
    const double halfLength = 1.0 + 2.0 * CellNoise(k, 1, 15);
    const double halfWidth = 0.1 + 0.3 * CellNoise(k, 1, 16);
    const double hx = alongX ? halfLength : halfWidth;
    const double hy = alongX ? halfWidth : halfLength;
    boards.push_back({ x - hx, x + hx, y - hy, y + hy, z, z + 0.04 });
  }
  append->AddInputData(MakeBoxes(boards));
  append->Update();
  return append->GetOutput();
}

/** A table, a shelf, a pillar and a ball inside the room. */
std::vector<std::array<double, 6>> RoomFurniture(const RoomLayout& room)
{
  const double h = room.Height;
  return {
    { -4.0, 4.0, -2.0, 2.0, 0.36 * h, 0.38 * h },            // table top
    { -3.8, -3.5, -1.8, -1.5, 0.0, 0.36 * h },               // its legs
    { 3.5, 3.8, -1.8, -1.5, 0.0, 0.36 * h },
    { -3.8, -3.5, 1.5, 1.8, 0.0, 0.36 * h },
    { 3.5, 3.8, 1.5, 1.8, 0.0, 0.36 * h },
    { room.HalfX - 1.2, room.HalfX, -5.0, 5.0, 0.5 * h, 0.52 * h }, // shelf on a wall
    { -7.0, -6.0, 4.0, 5.0, 0.0, h },                        // floor-to-ceiling pillar
  };
}
} // namespace

// A translucent square of `side` at (x, y, height), of colour and opacity.
void AddPane(vtkRenderer* renderer, double x, double y, double height, double side,
  const Color& color, double opacity)
{
  vtkNew<vtkPlaneSource> pane;
  pane->SetOrigin(x - 0.5 * side, y - 0.5 * side, height);
  pane->SetPoint1(x + 0.5 * side, y - 0.5 * side, height);
  pane->SetPoint2(x - 0.5 * side, y + 0.5 * side, height);
  pane->SetResolution(8, 8);
  AddActor(renderer, pane->GetOutputPort(), color, 0.3)->GetProperty()->SetOpacity(opacity);
}

// A pane whose colour and opacity vary across it: point scalars through a
// lookup table with alpha, as a coloured, partly transparent slice shows.
void AddScalarPane(vtkRenderer* renderer, double x, double y, double height, double side)
{
  vtkNew<vtkPlaneSource> pane;
  pane->SetOrigin(x - 0.5 * side, y - 0.5 * side, height);
  pane->SetPoint1(x + 0.5 * side, y - 0.5 * side, height);
  pane->SetPoint2(x - 0.5 * side, y + 0.5 * side, height);
  pane->SetResolution(16, 16);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(pane->GetOutputPort());
  elevation->SetLowPoint(x - 0.5 * side, y, height);
  elevation->SetHighPoint(x + 0.5 * side, y, height);
  vtkNew<vtkLookupTable> table;
  table->SetHueRange(0.66, 0.0);
  table->SetAlphaRange(0.2, 0.8);
  table->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(elevation->GetOutputPort());
  mapper->SetLookupTable(table);
  mapper->SetScalarRange(0.0, 1.0);
  vtkSmartPointer<vtkActor> actor = AddActorWithMapper(renderer, mapper, GroundColor, 0.3);
  mapper->ScalarVisibilityOn();
}

// Opts every translucent actor of the renderer out of casting shadows.
void KeepFromCasting(vtkProp* prop)
{
  vtkNew<vtkInformation> keys;
  keys->Set(vtkAbstractShadowMapPass::CASTS_SHADOWS(), 0);
  prop->SetPropertyKeys(keys);
}

void KeepTranslucentActorsFromCasting(vtkRenderer* renderer)
{
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    if (actor->HasTranslucentPolygonalGeometry())
    {
      KeepFromCasting(actor);
    }
  }
}

void BuildGlassScene(vtkRenderer* renderer)
{
  renderer->SetBackground(BackgroundColor.r, BackgroundColor.g, BackgroundColor.b);
  AddGround(renderer, -40.0, 40.0, -40.0, 40.0, 0.0);
  // Overlapping panes of three colours and opacities at three heights.
  AddPane(renderer, -6.0, 2.0, 4.0, 8.0, { 0.9, 0.2, 0.15 }, 0.3);
  AddPane(renderer, -2.0, -1.0, 6.0, 8.0, { 0.2, 0.8, 0.3 }, 0.5);
  AddPane(renderer, -4.0, -4.0, 8.0, 6.0, { 0.2, 0.35, 0.95 }, 0.7);
  AddScalarPane(renderer, 10.0, 8.0, 5.0, 8.0);
  // A closed translucent shell (two crossings) and an opaque sphere inside a
  // translucent one; opaque poles for contacts.
  vtkNew<vtkSphereSource> shell;
  shell->SetCenter(9.0, -6.0, 4.0);
  shell->SetRadius(3.0);
  shell->SetThetaResolution(48);
  shell->SetPhiResolution(24);
  AddActor(renderer, shell->GetOutputPort(), { 0.95, 0.8, 0.2 }, 0.4)->GetProperty()->SetOpacity(0.35);
  vtkNew<vtkSphereSource> core;
  core->SetCenter(9.0, -6.0, 4.0);
  core->SetRadius(1.0);
  AddActor(renderer, core->GetOutputPort(), SphereColor, 0.5);
  AddPoles(renderer);
  const double position[3] = { 30.0, -32.0, 26.0 };
  const double focalPoint[3] = { 0.0, 0.0, 2.0 };
  SetCamera(renderer, position, focalPoint, 40.0);
}

// A plume of smoke: three overlapping puffs of density rising along a
// diagonal, as a vtkVolume of image data whose opacity rises with the density
// and whose colour warms from blue-grey to orange in the dense cores.
void AddSmoke(vtkRenderer* renderer)
{
  struct Puff
  {
    glm::dvec3 Centre;
    double Radius;
  };
  const Puff puffs[] = { { { -2.0, -4.0, 6.0 }, 3.5 }, { { 1.0, -2.0, 9.0 }, 3.0 },
    { { 4.0, 0.0, 12.0 }, 2.5 } };
  vtkNew<vtkImageData> field;
  field->SetDimensions(48, 48, 36);
  field->SetOrigin(-8.0, -10.0, 2.0);
  field->SetSpacing(16.0 / 47.0, 16.0 / 47.0, 14.0 / 35.0);
  vtkNew<vtkFloatArray> density;
  density->SetName("density");
  density->SetNumberOfTuples(field->GetNumberOfPoints());
  for (vtkIdType i = 0; i < field->GetNumberOfPoints(); ++i)
  {
    double p[3];
    field->GetPoint(i, p);
    double value = 0.0;
    for (const Puff& puff : puffs)
    {
      const double r = glm::length(glm::dvec3(p[0], p[1], p[2]) - puff.Centre) / puff.Radius;
      value = std::max(value, std::exp(-2.0 * r * r));
    }
    density->SetValue(i, static_cast<float>(value));
  }
  field->GetPointData()->SetScalars(density);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.05, 0.0);
  opacity->AddPoint(1.0, 0.35);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.75, 0.8, 0.9);
  color->AddRGBPoint(1.0, 0.95, 0.6, 0.3);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetInterpolationTypeToLinear();
  vtkNew<vtkSmartVolumeMapper> mapper;
  mapper->SetInputData(field);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
}

void KeepVolumesFromCasting(vtkRenderer* renderer)
{
  vtkVolumeCollection* volumes = renderer->GetVolumes();
  vtkCollectionSimpleIterator it;
  volumes->InitTraversal(it);
  while (vtkVolume* volume = volumes->GetNextVolume(it))
  {
    KeepFromCasting(volume);
  }
}

void BuildSmokeScene(vtkRenderer* renderer)
{
  renderer->SetBackground(BackgroundColor.r, BackgroundColor.g, BackgroundColor.b);
  AddGround(renderer, -40.0, 40.0, -40.0, 40.0, 0.0);
  AddSmoke(renderer);
  AddPoles(renderer);
  AddSphere(renderer);
  const double position[3] = { 30.0, -32.0, 26.0 };
  const double focalPoint[3] = { 0.0, 0.0, 4.0 };
  SetCamera(renderer, position, focalPoint, 40.0);
}

void BuildDefaultScene(vtkRenderer* renderer)
{
  renderer->SetBackground(BackgroundColor.r, BackgroundColor.g, BackgroundColor.b);
  AddGround(renderer, -130.0, 70.0, -100.0, 100.0, 0.0);
  AddPoles(renderer);
  AddIsosurface(renderer);
  AddSphere(renderer);

  // Low over the ground looking along the row towards -x: a sun from the
  // default azimuth (60 degrees, behind the camera on its right) lights the
  // fronts and casts the shadows to the left and away from the viewer.
  const double position[3] = { 50.0, -10.0, 7.0 };
  const double focalPoint[3] = { -10.0, 2.0, 1.0 };
  SetCamera(renderer, position, focalPoint, 40.0);
}

bool BuildFileScene(
  vtkRenderer* renderer, const std::string& path, UpAxis up, ModelUp& chosen, std::string& error)
{
  const std::string extension = LowerCaseExtension(path);
  if (!IsSupportedModelExtension(extension))
  {
    error = "unsupported model format '" + path +
      "' (expected .obj, .ply, .stl, .vtp, .gltf or .glb)";
    return false;
  }
  if (!IsReadableFile(path))
  {
    error = "cannot read model '" + path + "': no such readable file";
    return false;
  }
  ReadFailure failure = ReadFailure::None;
  vtkSmartPointer<vtkPolyData> model = ReadModelIsolated(path, extension, failure);
  if (failure != ReadFailure::None)
  {
    error = "cannot read model '" + path + "': " + Describe(failure);
    return false;
  }
  std::array<double, 6> read{};
  model->GetBounds(read.data());
  chosen = ChooseModelUp(up, extension, read);
  model = WithNormals(TurnedUp(model, chosen.Axis));

  double bounds[6];
  model->GetBounds(bounds);
  const double size =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1e-6 });
  const double centerX = 0.5 * (bounds[0] + bounds[1]);
  const double centerY = 0.5 * (bounds[2] + bounds[3]);
  const double groundHalfSide = 2.0 * size; // ground is 4x the model's size
  // Slightly below the model so flat model bottoms do not z-fight with it.
  const double groundZ = bounds[4] - 1e-3 * size;

  renderer->SetBackground(BackgroundColor.r, BackgroundColor.g, BackgroundColor.b);
  AddGround(renderer, centerX - groundHalfSide, centerX + groundHalfSide,
    centerY - groundHalfSide, centerY + groundHalfSide, groundZ);
  AddActor(renderer, model, ModelColor, 0.3);
  FrameModel(renderer, bounds);
  return true;
}

bool IsLightKind(const std::string& kind)
{
  return kind == "sun" || kind == "spot" || kind == "point";
}

bool AddLight(
  vtkRenderer* renderer, const std::string& kind, double azimuthDeg, double elevationDeg)
{
  if (!IsLightKind(kind))
  {
    return false;
  }
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();

  const SceneSphere scene = VisibleSceneSphere(renderer);
  double direction[3];
  DirectionFromAngles(azimuthDeg, elevationDeg, direction);

  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetColor(1.0, 1.0, 1.0);
  light->SetIntensity(1.0);
  light->SetFocalPoint(scene.center[0], scene.center[1], scene.center[2]);

  double distance = 1.0; // sun: only the direction matters
  if (kind == "sun")
  {
    light->SetPositional(false);
  }
  else if (kind == "spot")
  {
    light->SetPositional(true);
    light->SetConeAngle(35.0);
    distance = 1.2 * scene.radius;
  }
  else // point
  {
    light->SetPositional(true);
    light->SetConeAngle(180.0);
    direction[0] = 0.0;
    direction[1] = 0.0;
    direction[2] = 1.0;
    distance = 0.3 * scene.radius;
  }
  light->SetPosition(scene.center[0] + distance * direction[0],
    scene.center[1] + distance * direction[1], scene.center[2] + distance * direction[2]);
  renderer->AddLight(light);
  return true;
}

// --- the benchmark's scenes ------------------------------------------------------

void BuildOutdoorScene(vtkRenderer* renderer)
{
  renderer->SetBackground(BackgroundColor.r, BackgroundColor.g, BackgroundColor.b);
  AddGround(renderer, -OutdoorHalfSide, OutdoorHalfSide, -OutdoorHalfSide, OutdoorHalfSide, 0.0);
  const std::vector<Ball>& balls = OutdoorBalls();
  AddActor(renderer, MakePoles(PlacePoles(balls)), PoleColor, 0.3);
  AddActor(renderer, MakeBalls(balls), SphereColor, 0.5);

  const double* position = OutdoorCameraPosition;
  const double focalPoint[3] = { position[0], position[1] + OutdoorFocalDistance, position[2] };
  SetCamera(renderer, position, focalPoint, OutdoorViewAngleDeg);
  renderer->GetActiveCamera()->SetClippingRange(OutdoorNearPlane, OutdoorFarPlane);
}

void BuildParaViewScene(vtkRenderer* renderer)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  renderer->SetBackground(BackgroundColor.r, BackgroundColor.g, BackgroundColor.b);
  AddGround(renderer, -ParaViewGroundHalfSide, ParaViewGroundHalfSide, -ParaViewGroundHalfSide,
    ParaViewGroundHalfSide, ParaViewGroundZ);
  AddActor(renderer, WaveletIsosurface(wavelet->GetOutputPort()), IsosurfaceColor, 0.4);
  AddColorMappedActor(renderer, WaveletSlice(wavelet->GetOutputPort()), WaveletScalarRange);
  AddActor(renderer, GradientStreamTubes(wavelet->GetOutputPort()), StreamTubeColor, 0.5);

  double direction[3];
  DirectionFromAngles(ParaViewCameraAzimuthDeg, ParaViewCameraElevationDeg, direction);
  double position[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    position[axis] = ParaViewFocalPoint[axis] + ParaViewCameraDistance * direction[axis];
  }
  SetCamera(renderer, position, ParaViewFocalPoint, 30.0);
  HoldClippingRangeAlongCameraPath(renderer->GetActiveCamera());
}

namespace
{
/// The contour whose value the time steps change: its own type, so that
/// AdvanceTimeVaryingData leaves the other scenes' contours alone.
class TimeVaryingContour : public vtkContourFilter
{
public:
  static TimeVaryingContour* New();
  vtkTypeMacro(TimeVaryingContour, vtkContourFilter);
};
vtkStandardNewMacro(TimeVaryingContour);

/// A data set of many time steps as a reader of a file series delivers it:
/// every step's surface made once, SetStep choosing one (as a reader's time
/// step index does), each execution handing on that step's arrays.
class TimeStepSeries : public vtkPolyDataAlgorithm
{
public:
  static TimeStepSeries* New();
  vtkTypeMacro(TimeStepSeries, vtkPolyDataAlgorithm);

  void AddStep(vtkPolyData* surface) { this->Steps.emplace_back(surface); }

  void SetStep(int step)
  {
    const int count = static_cast<int>(this->Steps.size());
    const int chosen = count > 0 ? ((step % count) + count) % count : 0;
    if (chosen != this->Step)
    {
      this->Step = chosen;
      this->Modified();
    }
  }

protected:
  TimeStepSeries() { this->SetNumberOfInputPorts(0); }

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs) override
  {
    vtkPolyData* output = vtkPolyData::GetData(outputs);
    if (this->Step < static_cast<int>(this->Steps.size()))
    {
      output->ShallowCopy(this->Steps[this->Step]);
    }
    return 1;
  }

private:
  std::vector<vtkSmartPointer<vtkPolyData>> Steps;
  int Step = 0;
};
vtkStandardNewMacro(TimeStepSeries);

/// Steps of the time-step series: the contour's first values, each step a
/// surface of its own (about 30 MB each).
constexpr int TimeStepCount = 6;

constexpr int ContourHalfExtent = 110;
/// The contour's value swings around 160 (RTData's mid-range), where the
/// surface's area changes least with it.
double ContourValueAt(int step)
{
  return 160.0 + 12.0 * std::sin(0.7 * step);
}
} // namespace

namespace
{
// A contour filter of type Contour over the wavelet, at the first step's value.
template <typename Contour>
vtkSmartPointer<Contour> ContourOfWavelet()
{
  const int h = ContourHalfExtent;
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-h, h, -h, h, -h, h);
  auto contour = vtkSmartPointer<Contour>::New();
  contour->SetInputConnection(wavelet->GetOutputPort());
  contour->SetValue(0, ContourValueAt(0));
  return contour;
}

// The contour scenes' ground, background and camera around `surface`.
void BuildIsosurfaceScene(vtkRenderer* renderer, vtkAlgorithmOutput* surface)
{
  const int h = ContourHalfExtent;
  renderer->SetBackground(BackgroundColor.r, BackgroundColor.g, BackgroundColor.b);
  AddGround(renderer, -4.0 * h, 4.0 * h, -4.0 * h, 4.0 * h, -1.3 * h);
  AddActor(renderer, surface, IsosurfaceColor, 0.4);

  const double focalPoint[3] = { 0.0, 0.0, -0.2 * h };
  double direction[3];
  DirectionFromAngles(ParaViewCameraAzimuthDeg, ParaViewCameraElevationDeg, direction);
  double position[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    position[axis] = focalPoint[axis] + 4.0 * h * direction[axis];
  }
  SetCamera(renderer, position, focalPoint, 30.0);
  HoldClippingRangeAlongCameraPath(renderer->GetActiveCamera());
}
} // namespace

void BuildContourScene(vtkRenderer* renderer)
{
  auto contour = ContourOfWavelet<TimeVaryingContour>();
  BuildIsosurfaceScene(renderer, contour->GetOutputPort());
}

void BuildTimeStepsScene(vtkRenderer* renderer)
{
  vtkNew<TimeStepSeries> series;
  for (int step = 0; step < TimeStepCount; ++step)
  {
    auto contour = ContourOfWavelet<vtkContourFilter>();
    contour->SetValue(0, ContourValueAt(step));
    contour->Update();
    // A copy of its own: the filter's output would keep the filter, and its
    // wavelet's 221^3 samples, alive.
    vtkNew<vtkPolyData> surface;
    surface->ShallowCopy(contour->GetOutput());
    series->AddStep(surface);
  }
  BuildIsosurfaceScene(renderer, series->GetOutputPort());
}

void BuildBigMeshScene(vtkRenderer* renderer)
{
  // Not a TimeVaryingContour: AdvanceTimeVaryingData leaves it alone.
  auto contour = ContourOfWavelet<vtkContourFilter>();
  vtkNew<vtkLinearSubdivisionFilter> finer;
  finer->SetInputConnection(contour->GetOutputPort());
  finer->SetNumberOfSubdivisions(1);
  BuildIsosurfaceScene(renderer, finer->GetOutputPort());
}

int AdvanceTimeVaryingData(vtkRenderer* renderer, int step)
{
  int advanced = 0;
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
  {
    vtkMapper* mapper = actor->GetMapper();
    vtkAlgorithm* input = mapper ? mapper->GetInputAlgorithm() : nullptr;
    if (auto* contour = TimeVaryingContour::SafeDownCast(input))
    {
      contour->SetValue(0, ContourValueAt(step));
    }
    else if (auto* series = TimeStepSeries::SafeDownCast(input))
    {
      series->SetStep(step);
    }
    else
    {
      continue;
    }
    input->Update();
    actor->Modified();
    ++advanced;
  }
  return advanced;
}

bool HasTimeVaryingData(const std::string& scene)
{
  return scene == "contour" || scene == "timesteps";
}

std::string ModelScenePath()
{
  return "/usr/share/assimp/models/STL/Spider_binary.stl";
}

bool BuildModelScene(vtkRenderer* renderer, std::string& error)
{
  const std::string path = ModelScenePath();
  if (!IsReadableFile(path))
  {
    error = "cannot read model '" + path +
      "': no such readable file (it comes with Debian's assimp-testmodels)";
    return false;
  }
  ModelUp up; // the spider's own axes: +z
  if (!BuildFileScene(renderer, path, UpAxis::PlusZ, up, error))
  {
    return false;
  }
  HoldClippingRangeAlongCameraPath(renderer->GetActiveCamera());
  return true;
}

std::vector<std::string> BenchmarkSceneNames()
{
  return { "outdoor", "paraview", "model" };
}

// --- the sweep's procedural scenes ---------------------------------------------------

double CityLayout::StreetCenter(int i) const
{
  return -0.5 * this->Blocks * this->Pitch + i * this->Pitch;
}

CityLayout GetCityLayout()
{
  return CityLayout();
}

void BuildCityScene(vtkRenderer* renderer)
{
  const CityLayout city = GetCityLayout();
  renderer->SetBackground(BackgroundColor.r, BackgroundColor.g, BackgroundColor.b);
  const double half = 0.5 * city.Blocks * city.Pitch + city.Pitch;
  AddGround(renderer, -half, half, -half, half, 0.0);
  AddActor(renderer, MakeBoxes(CityBuildings(city)), BuildingColor, 0.1);
  // Street level, looking down the street x = StreetCenter(1).
  const double position[3] = { city.StreetCenter(1), city.StreetCenter(0) - 10.0, 1.7 };
  const double focalPoint[3] = { position[0], position[1] + 30.0, 4.0 };
  SetCamera(renderer, position, focalPoint, 60.0);
}

void BuildFieldScene(vtkRenderer* renderer)
{
  renderer->SetBackground(BackgroundColor.r, BackgroundColor.g, BackgroundColor.b);
  const double half = 1.5 * FieldHalfSide;
  AddGround(renderer, -half, half, -half, half, 0.0);
  AddActor(renderer, MakeThinCasters(), PoleColor, 0.3);
  const double position[3] = { 0.0, -1.4 * FieldHalfSide, 12.0 };
  const double focalPoint[3] = { 0.0, 0.0, 0.0 };
  SetCamera(renderer, position, focalPoint, 40.0);
}

RoomLayout GetRoomLayout()
{
  return RoomLayout();
}

void BuildRoomScene(vtkRenderer* renderer)
{
  const RoomLayout room = GetRoomLayout();
  renderer->SetBackground(0.0, 0.0, 0.0);
  const double walls[6] = { -room.HalfX, room.HalfX, -room.HalfY, room.HalfY, 0.0, room.Height };
  AddActor(renderer, MakeBox(walls), WallColor, 0.05);
  AddActor(renderer, MakeBoxes(RoomFurniture(room)), FurnitureColor, 0.2);
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(5.0, 3.0, 1.5);
  ball->SetRadius(1.5);
  ball->SetThetaResolution(32);
  ball->SetPhiResolution(16);
  AddActor(renderer, ball->GetOutputPort(), SphereColor, 0.5);

  const double position[3] = { -0.8 * room.HalfX, -0.8 * room.HalfY, 0.6 * room.Height };
  const double focalPoint[3] = { 0.0, 0.0, 0.3 * room.Height };
  SetCamera(renderer, position, focalPoint, 70.0);
  const double lamp[3] = { 0.0, 0.0, 0.9 * room.Height };
  const double below[3] = { 0.0, 0.0, 0.0 };
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();
  renderer->AddLight(MakePositionalLight(lamp, below, 180.0));
}

std::vector<std::string> SweepSceneNames()
{
  return { "default", "outdoor", "paraview", "model", "city", "field", "room" };
}

void BuildStreetScene(vtkRenderer* renderer)
{
  renderer->SetBackground(BackgroundColor.r, BackgroundColor.g, BackgroundColor.b);
  AddGround(renderer, -80.0, 80.0, -40.0, 40.0, 0.0);
  vtkNew<vtkCubeSource> cube; // unit cube: each building scales it
  vtkNew<vtkCylinderSource> pole; // axis along y
  pole->SetRadius(0.08);
  pole->SetHeight(1.0);
  pole->SetResolution(12);
  for (int i = 0; i < StreetBuildingsPerSide; ++i)
  {
    for (const double side : { -1.0, 1.0 })
    {
      const double x = -75.0 + i * 2.5 + 0.6 * CellNoise(i, side > 0 ? 1 : 0, 3);
      const double height = 4.0 + 14.0 * CellNoise(i, side > 0 ? 1 : 0, 4);
      vtkSmartPointer<vtkActor> building = AddActor(renderer, cube->GetOutputPort(), ModelColor, 0.1);
      building->SetScale(2.0, 6.0, height);
      building->SetPosition(x, side * 12.0, 0.5 * height);
    }
  }
  for (int i = 0; i < StreetPolesPerSide; ++i)
  {
    for (const double side : { -1.0, 1.0 })
    {
      vtkSmartPointer<vtkActor> actor = AddActor(renderer, pole->GetOutputPort(), PoleColor, 0.3);
      actor->SetOrientation(90.0, 0.0, 0.0); // y axis -> z axis
      actor->SetScale(1.0, 5.0, 1.0);
      actor->SetPosition(-77.0 + i * 3.0, side * 6.0, 2.5);
    }
  }
  const double position[3] = { -70.0, -2.0, 1.7 };
  const double focalPoint[3] = { 0.0, 2.0, 4.0 };
  SetCamera(renderer, position, focalPoint, 50.0);
}

void BuildBlocksScene(vtkRenderer* renderer)
{
  renderer->SetBackground(BackgroundColor.r, BackgroundColor.g, BackgroundColor.b);
  const double spacing = 2.0;
  const double half = 0.5 * spacing * BlocksPerSide;
  AddGround(renderer, -half - 4.0, half + 4.0, -half - 4.0, half + 4.0, 0.0);
  vtkNew<vtkCubeSource> cube; // unit cube: each block scales it
  for (int i = 0; i < BlocksPerSide; ++i)
  {
    for (int j = 0; j < BlocksPerSide; ++j)
    {
      const double height = 0.5 + 3.0 * CellNoise(i, j, 5);
      vtkSmartPointer<vtkActor> block = AddActor(renderer, cube->GetOutputPort(), ModelColor, 0.1);
      block->SetScale(1.2, 1.2, height);
      block->SetPosition(-half + spacing * (i + 0.5), -half + spacing * (j + 0.5), 0.5 * height);
    }
  }
  const double position[3] = { -half - 20.0, -half - 25.0, 35.0 };
  const double focalPoint[3] = { 0.0, 0.0, 0.0 };
  SetCamera(renderer, position, focalPoint, 40.0);
}

namespace
{
using SceneBuilder = std::function<bool(vtkRenderer*, std::string&)>;

/// A builder that cannot fail.
template <void (*Build)(vtkRenderer*)>
bool Always(vtkRenderer* renderer, std::string&)
{
  Build(renderer);
  return true;
}

/// A scene, then some of its props kept from casting.
template <void (*Build)(vtkRenderer*), void (*KeepFromCasting)(vtkRenderer*)>
void BuiltThenKeptFromCasting(vtkRenderer* renderer)
{
  Build(renderer);
  KeepFromCasting(renderer);
}

/// Every scene BuildSceneByName makes, by name, in the order SceneNames gives.
const std::vector<std::pair<std::string, SceneBuilder>>& SceneBuilders()
{
  static const std::vector<std::pair<std::string, SceneBuilder>> builders = {
    { "default", Always<BuildDefaultScene> },
    { "outdoor", Always<BuildOutdoorScene> },
    { "paraview", Always<BuildParaViewScene> },
    { "model", BuildModelScene },
    { "city", Always<BuildCityScene> },
    { "field", Always<BuildFieldScene> },
    { "room", Always<BuildRoomScene> },
    { "street", Always<BuildStreetScene> },
    { "blocks", Always<BuildBlocksScene> },
    { "glass", Always<BuildGlassScene> },
    { "glass-opaque",
      Always<BuiltThenKeptFromCasting<BuildGlassScene, KeepTranslucentActorsFromCasting>> },
    { "smoke", Always<BuildSmokeScene> },
    { "smoke-opaque",
      Always<BuiltThenKeptFromCasting<BuildSmokeScene, KeepVolumesFromCasting>> },
    { "contour", Always<BuildContourScene> },
    { "timesteps", Always<BuildTimeStepsScene> },
    { "bigmesh", Always<BuildBigMeshScene> },
  };
  return builders;
}
} // namespace

std::vector<std::string> SceneNames()
{
  std::vector<std::string> names;
  for (const auto& builder : SceneBuilders())
  {
    names.push_back(builder.first);
  }
  return names;
}

bool BuildSceneByName(vtkRenderer* renderer, const std::string& name, std::string& error)
{
  const auto& builders = SceneBuilders();
  const auto builder = std::find_if(
    builders.begin(), builders.end(), [&](const auto& entry) { return entry.first == name; });
  if (builder != builders.end())
  {
    return builder->second(renderer, error);
  }
  std::string known;
  for (const auto& entry : builders)
  {
    known += (known.empty() ? "" : ", ") + entry.first;
  }
  error = "unknown scene '" + name + "' (expected one of " + known + ")";
  return false;
}

std::vector<std::string> LightSetupNames()
{
  return { "overhead", "perpendicular", "behind", "facing", "spot", "point", "wide-spot",
    "street-point", "lamp-behind" };
}

std::vector<std::string> SizedLightSetupNames()
{
  return { "soft-sun", "soft-spot", "soft-point" };
}

std::string LightKindOfSetup(const std::string& setup)
{
  if (setup == "spot" || setup == "wide-spot" || IsSizedLampSetup(setup, "soft-spot"))
  {
    return "spot";
  }
  return setup == "point" || setup == "street-point" || setup == "lamp-behind" ||
      IsSizedLampSetup(setup, "soft-point")
    ? "point"
    : "sun";
}

bool IsSizedLightSetup(const std::string& setup)
{
  const std::vector<std::string> names = SizedLightSetupNames();
  return std::find(names.begin(), names.end(), setup) != names.end() ||
    WiderSunDiameter(setup) > 0.0 || LargerLampPercent(setup) > 0.0;
}

bool IsLightSetup(const std::string& setup)
{
  const std::vector<std::string> names = LightSetupNames();
  return std::find(names.begin(), names.end(), setup) != names.end() || IsSizedLightSetup(setup);
}

bool AddLightSetup(vtkRenderer* renderer, const std::string& setup)
{
  if (!IsLightSetup(setup))
  {
    return false;
  }
  const ViewFrame view = ViewFrameOf(renderer->GetActiveCamera());
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();
  renderer->AddLight(MakeSetupLight(view, setup));
  return true;
}

void SetCameraPathFrame(
  vtkCamera* initial, vtkCamera* camera, int frame, int frameCount, double yawDegrees)
{
  if (!initial || !camera || initial == camera)
  {
    return;
  }
  camera->DeepCopy(initial); // clipping range, view angle, ... stay the initial ones
  const double t =
    frameCount > 1 ? std::clamp(static_cast<double>(frame) / (frameCount - 1), 0.0, 1.0) : 0.0;

  double position[3];
  double direction[3];
  double viewUp[3];
  initial->GetPosition(position);
  initial->GetDirectionOfProjection(direction);
  initial->GetViewUp(viewUp);
  const double distance = initial->GetDistance();
  const double dolly = t * CameraPathDollyFraction * distance;
  for (int axis = 0; axis < 3; ++axis)
  {
    position[axis] += dolly * direction[axis];
  }
  // Turn about the world's +z axis through the (moved) camera.
  const double yaw = vtkMath::RadiansFromDegrees(t * yawDegrees);
  RotateAboutZ(direction, yaw);
  RotateAboutZ(viewUp, yaw);
  camera->SetPosition(position);
  camera->SetFocalPoint(position[0] + distance * direction[0],
    position[1] + distance * direction[1], position[2] + distance * direction[2]);
  camera->SetViewUp(viewUp);
}

} // namespace shadowscenes
