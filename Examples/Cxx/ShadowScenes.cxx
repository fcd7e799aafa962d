#include "ShadowScenes.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkAlgorithm.h>
#include <vtkAppendPolyData.h>
#include <vtkCamera.h>
#include <vtkContourFilter.h>
#include <vtkCylinderSource.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkGLTFReader.h>
#include <vtkLight.h>
#include <vtkMath.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRTAnalyticSource.h>
#include <vtkRenderer.h>
#include <vtkSMPTools.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <new>

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

} // namespace

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

bool BuildFileScene(vtkRenderer* renderer, const std::string& path, std::string& error)
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
  model = WithNormals(model);

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

} // namespace shadowscenes
