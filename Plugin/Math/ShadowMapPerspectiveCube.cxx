#include "ShadowMapPerspectiveCube.h"

#include "ShadowMapPerspective.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowmaps
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

// Tangent window (x / Z, y / Z) and depth range Z = -z of points in a light
// camera's view; invalid when a point is not in front of it.
struct FaceWindow
{
  glm::dvec2 Lo{ Infinity }, Hi{ -Infinity };
  double Near = Infinity, Far = 0.0;
  bool Valid = true;

  void Add(const glm::dvec3& q)
  {
    const double depth = -q.z;
    if (!(depth > 0.0) || !IsFiniteVector(q))
    {
      this->Valid = false;
      return;
    }
    this->Near = std::min(this->Near, depth);
    this->Far = std::max(this->Far, depth);
    this->Lo = glm::min(this->Lo, glm::dvec2(q) / depth);
    this->Hi = glm::max(this->Hi, glm::dvec2(q) / depth);
  }
};

// The window of face `face`'s whole platform, seen by the face's camera
// `faceView` (post-perspective space to the face's view).
FaceWindow PlatformWindow(const glm::dmat4& faceView, const Aabb& box, int face)
{
  const int axis = face / 2;
  FaceWindow window;
  for (glm::dvec3 corner : box.Corners())
  {
    corner[axis] = face % 2 == 0 ? box.Max[axis] : box.Min[axis];
    window.Add(ProjectPoint(faceView, corner));
  }
  return window;
}

// A perspective frustum over the tangent window, for its side planes.
glm::dmat4 WindowFrustum(const FaceWindow& window)
{
  return glm::frustum(window.Lo.x, window.Hi.x, window.Lo.y, window.Hi.y, 1.0, 2.0);
}

// The receivers of a face: those inside `receivers` and the pyramid from the
// light through the face's platform (`platform`, the face's frustum over it).
std::vector<glm::dvec3> FaceBody(
  const std::vector<Plane>& receivers, const glm::dmat4& platform, double scale)
{
  std::vector<Plane> planes = receivers;
  const std::array<Plane, 6> sides = FrustumPlanes(platform);
  planes.insert(planes.end(), sides.begin(), sides.begin() + 4);
  return ConvexPolytopeVertices(planes, scale);
}

// The face depth at which the face's pyramid (the window `window` seen from
// the light, the origin of the face's view) first reaches `reach` from the
// light in the world, over its corners' edges; 0 for no reach (a sun). Found
// by bisection along each edge: post-perspective space magnifies the world
// around a light near the camera's plane by far more than around a light far
// from it, so no fixed share of the face's depth range, nor a derivative at
// the light, says where the world's reach ends.
double NearPlaneWithin(const glm::dmat4& toFace, const FaceWindow& window, double reach)
{
  if (!(reach > 0.0))
  {
    return 0.0;
  }
  const glm::dmat4 toWorld = glm::inverse(toFace);
  const glm::dvec3 light = ProjectPoint(toWorld, glm::dvec3(0.0));
  double near = window.Far;
  for (const double x : { window.Lo.x, window.Hi.x })
  {
    for (const double y : { window.Lo.y, window.Hi.y })
    {
      const auto withinReach = [&](double depth) {
        const glm::dvec3 p = ProjectPoint(toWorld, depth * glm::dvec3(x, y, -1.0));
        return IsFiniteVector(p) && glm::length(p - light) < reach;
      };
      double lo = 0.0;
      double hi = near;
      if (withinReach(hi))
      {
        continue;
      }
      for (int step = 0; step < 60; ++step)
      {
        const double mid = 0.5 * (lo + hi);
        (withinReach(mid) ? lo : hi) = mid;
      }
      near = lo;
    }
  }
  return near;
}

// The face's map cropped to its receivers `body`, seen through `toFace` (world
// to the face's view). The near plane lies at half the nearest receiver's
// depth, casters nearer the light clamped onto it, but never nearer the light
// than `nearReach` in the world: receivers that near it are left unshadowed.
// A light among the receivers is the apex of its faces' bodies (depth within
// `apex` of 0): the other vertices bound the window, and the near plane is
// the reach's.
bool FitFace(const glm::dmat4& toFace, const std::vector<glm::dvec3>& body, bool inverse,
  int resolution, double marginTexels, double apex, double nearReach, LightView& view)
{
  FaceWindow window;
  bool apexInBody = false;
  for (const auto& p : body)
  {
    const glm::dvec3 q = ProjectPoint(toFace, p);
    if (std::abs(q.z) <= apex)
    {
      apexInBody = true;
      continue;
    }
    window.Add(q);
  }
  if (!window.Valid || !(window.Far > 0.0))
  {
    return false;
  }
  const double nearLight = NearPlaneWithin(toFace, window, nearReach);
  const double zNear = apexInBody ? nearLight : std::max(0.5 * window.Near, nearLight);
  const glm::dvec2 size = glm::max(window.Hi - window.Lo, glm::dvec2(1e-12));
  const glm::dvec2 margin = size * (marginTexels / std::max(resolution, 1));
  const glm::dvec2 lo = window.Lo - margin;
  const glm::dvec2 hi = window.Hi + margin;
  view.View = toFace;
  if (inverse)
  {
    view.Projection = InverseProjection(lo, hi, 0.999 * window.Near);
  }
  else
  {
    // As FitPerspective's point lights: casters nearer the light are clamped
    // onto a near plane kept close to the receivers, where depth needs its
    // precision. The far plane a little beyond the farthest receiver, for the
    // moves of a drag that keeps the cube (KeptCubeServes).
    view.Projection =
      glm::frustum(lo.x * zNear, hi.x * zNear, lo.y * zNear, hi.y * zNear, zNear, window.Far * 1.01);
  }
  view.Perspective = true;
  view.TexelSizeFromGradient = true;
  return IsFinite(view.ViewProjection());
}

// The farthest the scene reaches from a positional light (0 for a sun, which
// no receiver is near).
double ReachFromLight(const Aabb& scene, const glm::dvec4& towardLight)
{
  if (towardLight.w == 0.0)
  {
    return 0.0;
  }
  const glm::dvec3 light = glm::dvec3(towardLight) / towardLight.w;
  double farthest = 0.0;
  for (const auto& corner : scene.Corners())
  {
    farthest = std::max(farthest, glm::length(corner - light));
  }
  return farthest;
}

// The receivers' box in post-perspective space; empty when one lies on or
// behind the virtual camera's plane.
Aabb PostPerspectiveBox(const glm::dmat4& postPerspective, const std::vector<glm::dvec3>& body)
{
  Aabb box;
  for (const auto& p : body)
  {
    const glm::dvec4 q = postPerspective * glm::dvec4(p, 1.0);
    if (!(q.w > 0.0))
    {
      return Aabb{};
    }
    box.Add(glm::dvec3(q) / q.w);
  }
  return box;
}
} // namespace

glm::dvec3 PerspectiveCubeAxis(int face)
{
  glm::dvec3 axis(0.0);
  axis[face / 2] = face % 2 == 0 ? 1.0 : -1.0;
  return axis;
}

double PlatformDistance(const Aabb& box, const glm::dvec3& light, int face)
{
  const int axis = face / 2;
  return face % 2 == 0 ? box.Max[axis] - light[axis] : light[axis] - box.Min[axis];
}

int DisplacedCubeFace(const Aabb& box, const glm::dvec3& light, const glm::dvec3& point)
{
  int best = -1;
  double largest = 0.0;
  for (int face = 0; face < PerspectiveCubeFaces; ++face)
  {
    const double distance = PlatformDistance(box, light, face);
    if (!(distance > 0.0))
    {
      continue;
    }
    const double reach = glm::dot(point - light, PerspectiveCubeAxis(face)) / distance;
    if (reach > largest)
    {
      largest = reach;
      best = face;
    }
  }
  return best;
}

PerspectiveCube FitPerspectiveCube(const glm::dmat4& cameraView, const glm::dmat4& cameraProjection,
  const std::vector<Plane>& receivers, const Aabb& scene, const glm::dvec4& towardLight,
  int resolution, double slideBack, double marginTexels)
{
  PerspectiveCube cube;
  const bool parallel = cameraProjection[2][3] == 0.0;
  if (parallel || !IsFinite(cameraView) || !IsFinite(cameraProjection) || scene.IsEmpty())
  {
    return cube;
  }
  const double scale = std::max(scene.Diagonal(), 1e-300);
  const std::vector<glm::dvec3> body = ConvexPolytopeVertices(receivers, scale);
  if (body.empty())
  {
    return cube;
  }
  const double slide =
    std::max(slideBack, SlideBackHoldingCasters(cameraView, body, scene, towardLight));
  cube.PostPerspective = SlideBackPostPerspective(cameraView, cameraProjection, slide);
  cube.Platforms = PostPerspectiveBox(cube.PostPerspective, body);
  const glm::dvec4 light = cube.PostPerspective * towardLight;
  if (cube.Platforms.IsEmpty() || StaysDirectional(light, 0.5 * cube.Platforms.Diagonal()))
  {
    return cube;
  }
  cube.Inverse = light.w < 0.0;
  cube.LightPosition = glm::dvec3(light) / light.w;
  // A face whose platform passes (nearly) through the light would need a
  // half-space; the faces beside it hold its receivers' rays but for a sliver.
  const double tiny = 1e-9 * std::max(cube.Platforms.Diagonal(), 1e-300);
  const double step = scale * 1e-5;
  // A light among the receivers: its faces' near plane at a hundredth of the
  // scene's reach from it in the world (the uniform cube faces' is at a
  // thousandth). Post-perspective space spreads that world reach over many
  // times the depth range it gets in the light's own view, and at a thousandth
  // float depth left acne around a wide spot among the receivers (sweep seed
  // 3767396340924350328: 8.09% false shadows; at a hundredth none).
  const double nearReach = 1e-2 * ReachFromLight(scene, towardLight);
  for (int face = 0; face < PerspectiveCubeFaces; ++face)
  {
    LightView& view = cube.Faces[face];
    const glm::dmat4 faceView = LightLookAt(cube.LightPosition, PerspectiveCubeAxis(face));
    const glm::dmat4 toFace = faceView * cube.PostPerspective;
    view.View = toFace;
    view.Projection = glm::frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 2.0);
    view.OutOfView = true;
    const double distance = PlatformDistance(cube.Platforms, cube.LightPosition, face);
    const FaceWindow platform = PlatformWindow(faceView, cube.Platforms, face);
    if (!(distance > tiny) || !platform.Valid)
    {
      continue;
    }
    const std::vector<glm::dvec3> faceBody =
      FaceBody(receivers, WindowFrustum(platform) * toFace, scale);
    if (faceBody.empty())
    {
      continue; // no receiver picks it: its selection stays 0
    }
    cube.Selection[face] = 1.0 / distance;
    if (!FitFace(toFace, faceBody, cube.Inverse, resolution, marginTexels, tiny, nearReach, view))
    {
      return PerspectiveCube{};
    }
    view.OutOfView = false;
    for (const auto& p : faceBody)
    {
      view.TexelConstant =
        std::max(view.TexelConstant, WorldTexelSize(view, p, towardLight, step, resolution));
    }
  }
  cube.Valid = true;
  return cube;
}

namespace
{
// The plane h . (p, 1) >= 0.
Plane HomogeneousPlane(const glm::dvec4& h)
{
  const double length = glm::length(glm::dvec3(h));
  return length > 0.0 ? Plane{ glm::dvec3(h) / length, h.w / length } : Plane{};
}

// Whether the fresh cube leaves the receiver `p` before the near plane of the
// face that holds it (unshadowed; on the border between faces, before every
// such face's).
bool BeforeFreshNearPlane(const PerspectiveCube& cube, const glm::dvec3& p)
{
  std::array<glm::dvec4, PerspectiveCubeFaces> clips;
  double largest = 0.0;
  for (int face = 0; face < PerspectiveCubeFaces; ++face)
  {
    clips[face] = cube.Faces[face].ViewProjection() * glm::dvec4(p, 1.0);
    largest = std::max(largest, clips[face].w * cube.Selection[face]);
  }
  bool before = largest > 0.0;
  for (int face = 0; face < PerspectiveCubeFaces && before; ++face)
  {
    if (clips[face].w * cube.Selection[face] >= largest * (1.0 - 1e-9))
    {
      before = clips[face].z < -clips[face].w;
    }
  }
  return before;
}

// The world region whose receivers `selection` gives to face `face`: where its
// weighted clip w is positive and at least every other face's.
std::vector<Plane> SelectionRegion(
  const std::vector<LightView>& faces, const std::vector<double>& selection, size_t face)
{
  const glm::dvec4 own = glm::transpose(faces[face].ViewProjection())[3] * selection[face];
  std::vector<Plane> planes{ HomogeneousPlane(own) };
  for (size_t other = 0; other < faces.size(); ++other)
  {
    if (other != face && selection[other] > 0.0)
    {
      planes.push_back(
        HomogeneousPlane(own - glm::transpose(faces[other].ViewProjection())[3] * selection[other]));
    }
  }
  return planes;
}


// The vertices of the receivers `selection` gives to each face (none for a
// face it gives none).
std::array<std::vector<glm::dvec3>, PerspectiveCubeFaces> ReceiversOfFaces(
  const std::vector<LightView>& faces, const std::vector<double>& selection,
  const std::vector<Plane>& receivers, double scale)
{
  std::array<std::vector<glm::dvec3>, PerspectiveCubeFaces> bodies;
  for (size_t face = 0; face < faces.size(); ++face)
  {
    if (selection[face] > 0.0)
    {
      std::vector<Plane> planes = receivers;
      const std::vector<Plane> region = SelectionRegion(faces, selection, face);
      planes.insert(planes.end(), region.begin(), region.end());
      bodies[face] = ConvexPolytopeVertices(planes, scale);
    }
  }
  return bodies;
}

// The coarsest texel of `face` over the receivers `body` it is given, the
// light's own position (a light among them: the faces' apex) left out.
double CoarsestTexel(const LightView& face, const std::vector<glm::dvec3>& body,
  const glm::dvec4& towardLight, double step, int resolution)
{
  const glm::dmat4 map = face.ViewProjection();
  double farthest = 0.0;
  for (const auto& p : body)
  {
    farthest = std::max(farthest, (map * glm::dvec4(p, 1.0)).w);
  }
  double coarsest = 0.0;
  for (const auto& p : body)
  {
    if ((map * glm::dvec4(p, 1.0)).w > 1e-9 * farthest)
    {
      coarsest = std::max(coarsest, WorldTexelSize(face, p, towardLight, step, resolution));
    }
  }
  return coarsest;
}
// Whether `selection` gives every receiver inside `receivers` to a face: no
// part of them, more than a point (a light among them, where every face's w
// is 0), lies where every used face's weighted clip w is at most 0 (behind a
// light that was off a corner of the box the faces were fitted to).
bool SelectionCoversReceivers(const std::vector<LightView>& faces,
  const std::vector<double>& selection, const std::vector<Plane>& receivers, double scale)
{
  std::vector<Plane> planes = receivers;
  for (size_t face = 0; face < faces.size(); ++face)
  {
    if (selection[face] > 0.0)
    {
      planes.push_back(
        HomogeneousPlane(-glm::transpose(faces[face].ViewProjection())[3] * selection[face]));
    }
  }
  Aabb uncovered;
  for (const auto& p : ConvexPolytopeVertices(planes, scale))
  {
    uncovered.Add(p);
  }
  return uncovered.IsEmpty() || !(uncovered.Diagonal() > 1e-6 * scale);
}
} // namespace

FreshCube MeasureFreshCube(const PerspectiveCube& cube, const std::vector<Plane>& receivers,
  const Aabb& scene, const glm::dvec4& towardLight, int resolution)
{
  FreshCube fresh;
  fresh.Cube = cube;
  if (!cube.Valid)
  {
    return fresh;
  }
  const double scale = std::max(scene.Diagonal(), 1e-300);
  const std::vector<LightView> faces(cube.Faces.begin(), cube.Faces.end());
  const std::vector<double> selection(cube.Selection.begin(), cube.Selection.end());
  const auto bodies = ReceiversOfFaces(faces, selection, receivers, scale);
  for (int face = 0; face < PerspectiveCubeFaces; ++face)
  {
    fresh.CoarsestTexels[face] =
      CoarsestTexel(cube.Faces[face], bodies[face], towardLight, scale * 1e-5, resolution);
    fresh.Coarsest = std::max(fresh.Coarsest, fresh.CoarsestTexels[face]);
  }
  return fresh;
}

bool KeptCubeServes(const std::vector<LightView>& kept, const std::vector<double>& selection,
  const std::vector<Plane>& receivers, const FreshCube& fresh, const Aabb& scene,
  const glm::dvec4& towardLight, int resolution, double maximumTexelRatio, double reachTexels)
{
  if (kept.size() != PerspectiveCubeFaces || selection.size() != kept.size() || !fresh.Cube.Valid)
  {
    return false;
  }
  const double scale = std::max(scene.Diagonal(), 1e-300);
  if (!SelectionCoversReceivers(kept, selection, receivers, scale))
  {
    return false;
  }
  const auto keptBodies = ReceiversOfFaces(kept, selection, receivers, scale);
  const double step = scale * 1e-5;
  const double inside = 1.0 - 2.0 * reachTexels / std::max(resolution, 1);
  for (int face = 0; face < PerspectiveCubeFaces; ++face)
  {
    const std::vector<glm::dvec3>& body = keptBodies[face];
    if (body.empty())
    {
      continue;
    }
    if (kept[face].OutOfView)
    {
      return false;
    }
    const glm::dmat4 map = kept[face].ViewProjection();
    double farthest = 0.0;
    for (const auto& p : body)
    {
      farthest = std::max(farthest, (map * glm::dvec4(p, 1.0)).w);
    }
    for (const auto& p : body)
    {
      const glm::dvec4 clip = map * glm::dvec4(p, 1.0);
      if (clip.w <= 1e-9 * farthest)
      {
        continue; // the light itself, among the receivers: the apex of its faces
      }
      const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
      // Before the near plane a receiver is unshadowed: only where the fresh
      // cube leaves it so too (within its reach of a light among the receivers).
      const bool beforeNear = ndc.z < -1.0 && !BeforeFreshNearPlane(fresh.Cube, p);
      if (!(std::abs(ndc.x) <= inside && std::abs(ndc.y) <= inside && ndc.z <= 1.0) || beforeNear)
      {
        return false;
      }
    }
    // Texels are compared face by face at their coarsest, not receiver by
    // receiver: the faces' borders move with the camera, and a receiver on a
    // kept face's border (where its texels are coarsest) may lie inside the
    // fresh cube's face, whose rim is elsewhere.
    const double reference =
      fresh.CoarsestTexels[face] > 0.0 ? fresh.CoarsestTexels[face] : fresh.Coarsest;
    if (reference > 0.0 &&
      !(CoarsestTexel(kept[face], body, towardLight, step, resolution) <=
        maximumTexelRatio * reference))
    {
      return false;
    }
  }
  return true;
}

} // namespace shadowmaps
