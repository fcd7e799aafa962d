// Scenes and lights shared by the vtkshadows program, the tests and the
// benchmarks. All scenes use +z as the up axis; models loaded from files are
// turned so that theirs is too (ShadowModelUp.h).
#ifndef ShadowScenes_h
#define ShadowScenes_h

#include "ShadowModelUp.h"

#include <string>
#include <vector>

class vtkCamera;
class vtkRenderer;

namespace shadowscenes
{

/**
 * The built-in scene: a 200 x 200 ground plane, a row of thin poles, an
 * isosurface of vtkRTAnalyticSource and a floating sphere, seen from a low
 * camera looking along the row so that shadows reach into the distance.
 */
void BuildDefaultScene(vtkRenderer* renderer);

/**
 * Loads an OBJ, PLY, STL, VTP, glTF or glb model (chosen by the extension,
 * case-insensitive), turns it so that its up axis (`up`, or ChooseModelUp's
 * choice for Auto, returned in `chosen`) is +z, puts it on a ground plane four
 * times its size and frames the camera on it from an elevated three-quarter
 * view. On failure (unknown extension, unreadable file, no geometry) returns
 * false, leaves the renderer untouched and sets `error` to a one-line message.
 */
bool BuildFileScene(vtkRenderer* renderer, const std::string& path, UpAxis up, ModelUp& chosen,
  std::string& error);

/** True for the light kinds AddLight understands: "sun", "spot", "point". */
bool IsLightKind(const std::string& kind);

/**
 * Replaces the renderer's lights by one scene light placed relative to the
 * bounds of the visible props (call it after building the scene):
 *  - sun:   directional, coming from azimuth/elevation (degrees; azimuth
 *           counter-clockwise from +x, elevation above the ground plane),
 *  - spot:  positional, 35 degree cone, at azimuth/elevation and 1.2 scene
 *           radii from the centre, aimed at the centre,
 *  - point: positional, 180 degree cone, 0.3 scene radii above the centre
 *           (azimuth and elevation are ignored).
 * Returns false, changing nothing, for an unknown kind.
 */
bool AddLight(vtkRenderer* renderer, const std::string& kind, double azimuthDeg,
  double elevationDeg);

// --- the benchmark's scenes ---------------------------------------------------
//
// Every benchmark scene puts its geometry in world coordinates (no actor
// transforms) and sets a camera and a clipping range that hold for the whole
// camera path (see SetCameraPathFrame): callers must call neither ResetCamera
// nor ResetCameraClippingRange afterwards.

/**
 * A 400 x 400 ground plane centred at the origin (z = 0), about 10,000 thin
 * poles (radius 0.12, height 3 to 5) on a jittered 4-unit grid over all of
 * it, and a few spheres: three near the camera (two resting on the ground, one
 * floating) and three far away. The camera stands 2 units above the ground in
 * a pole-free aisle and looks horizontally along +y; view angle 30 degrees,
 * clipping range [0.2, 300] so that the far plane cuts the ground.
 * ResetCamera would move the camera back until the whole ground is in view and
 * ResetCameraClippingRange would push the far plane out to the ground's far
 * corner: callers must call neither.
 * About 232,000 triangles: one polydata for the 9,977 poles (22 triangles
 * each), one for the spheres.
 */
void BuildOutdoorScene(vtkRenderer* renderer);

/**
 * ParaView-style visualisation of vtkRTAnalyticSource (its 20-unit box
 * centred at the origin) floating 5 units above a 400 x 400 ground plane: an
 * isosurface, a colour-mapped vertical slice and streamline tubes of the
 * field's gradient, so that they shadow the ground and each other. Elevated
 * three-quarter camera, view angle 30 degrees, clipping range widened from
 * ResetCameraClippingRange's for the camera path. About 49,000 triangles.
 */
void BuildParaViewScene(vtkRenderer* renderer);

/** The model BuildModelScene loads (from Debian's assimp-testmodels). */
std::string ModelScenePath();

/**
 * ModelScenePath() (a spider, +z up, 1,312 triangles) on a ground plane,
 * framed as by BuildFileScene, with the clipping range widened for the camera
 * path. Returns false with a one-line `error`, leaving the renderer
 * untouched, when the model cannot be read.
 */
bool BuildModelScene(vtkRenderer* renderer, std::string& error);

/** The benchmark's scenes, in order: "outdoor", "paraview", "model". */
std::vector<std::string> BenchmarkSceneNames();

// --- the sweep's procedural scenes (vtkshadows sweep) ---------------------------------

/** Square blocks of box buildings between streets, centred at the origin. */
struct CityLayout
{
  int Blocks = 6;          ///< blocks per side
  double Pitch = 24.0;     ///< from one street's centre line to the next
  double StreetWidth = 8.0;
  /// Centre line of street i (0..Blocks), along x or y.
  double StreetCenter(int i) const;
};
CityLayout GetCityLayout();

/**
 * GetCityLayout()'s blocks, each holding one building 6 to 40 units high or two
 * of different heights, in one polydata on a ground reaching one block past
 * the city; camera at street level (z = 1.7) looking down a street.
 */
void BuildCityScene(vtkRenderer* renderer);

/**
 * A scattered field of thin casters on a 90 x 90 ground: 240 rods (radius 0.03
 * to 0.12, 2 to 8 long, leaning up to 40 degrees) and 40 boards 4 cm thick
 * floating 0.5 to 4.5 units up, over the central 60 x 60; elevated camera.
 */
void BuildFieldScene(vtkRenderer* renderer);

/** A closed room, inner size 2 HalfX x 2 HalfY x Height, floor at z = 0. */
struct RoomLayout
{
  double HalfX = 12.0;
  double HalfY = 8.0;
  double Height = 8.0;
};
RoomLayout GetRoomLayout();

/**
 * GetRoomLayout()'s closed box (black background: nothing outside is seen from
 * inside) with a table, a shelf, a floor-to-ceiling pillar and a ball; camera
 * inside, one point light under the ceiling.
 */
void BuildRoomScene(vtkRenderer* renderer);

/// Actors of the street scene: a ground, buildings and poles on both sides.
constexpr int StreetBuildingsPerSide = 60;
constexpr int StreetPolesPerSide = 52;

/**
 * Many actors, for frame times where per-actor work counts: a street of
 * 2 x StreetBuildingsPerSide box buildings (one actor each) and
 * 2 x StreetPolesPerSide thin poles on a 160 x 80 ground (225 actors), camera
 * at street level looking along it.
 */
void BuildStreetScene(vtkRenderer* renderer);

constexpr int BlocksPerSide = 45;

/**
 * Thousands of actors, where the per-actor cost is the frame: a grid of
 * BlocksPerSide^2 (2,025) small boxes of varied heights on a ground, each box
 * an actor with its own mapper (as an application shows the blocks of a
 * dataset), seen from above at an angle.
 */
void BuildBlocksScene(vtkRenderer* renderer);

/**
 * Data that change every frame, as a time series or a dragged slider change
 * them: a wavelet of 221^3 samples contoured (about 780,000 triangles at
 * every value AdvanceTimeVaryingData gives it), floating over a ground, seen
 * as the paraview scene is.
 */
void BuildContourScene(vtkRenderer* renderer);

/**
 * A data set of many time steps, as a reader of a file series plays it: the
 * contour scene's surface at six values, each made once when the scene is
 * built (about 180 MB in all), AdvanceTimeVaryingData choosing the step (the
 * mapper's input then holds another surface's arrays), under the contour
 * scene's ground and camera.
 */
void BuildTimeStepsScene(vtkRenderer* renderer);

/**
 * A big still mesh: the contour scene's isosurface at its first value with
 * each triangle split in four (about 3.3 million triangles), over the same
 * ground, under the same camera. Its data do not change.
 */
void BuildBigMeshScene(vtkRenderer* renderer);

/**
 * Moves the renderer's time-varying data to time step `step`: the contour of
 * BuildContourScene takes the step's value, the series of BuildTimeStepsScene
 * its step (modulo its count), and updates (so a
 * render after it draws new geometry without running the filter), and its
 * actor is marked modified, as an application must for VTK's own
 * vtkShadowMapPass to render its map again: its baker pass compares the
 * lights' and props' times, not their data's, and keeps the first step's
 * shadow otherwise (this module's passes follow the data without it). Returns
 * how many it advanced: 0 for a scene without time-varying data.
 */
int AdvanceTimeVaryingData(vtkRenderer* renderer, int step);

/** True for the scenes whose data AdvanceTimeVaryingData plays: "contour", "timesteps". */
bool HasTimeVaryingData(const std::string& scene);

/** The sweep's scenes: "default", the benchmark's, then "city", "field", "room". */
std::vector<std::string> SweepSceneNames();

/**
 * Translucent casters over a ground: overlapping panes of three colours,
 * opacities and heights, a pane coloured by scalars through a lookup table
 * with alpha, a translucent shell round an opaque sphere, opaque poles.
 */
void BuildGlassScene(vtkRenderer* renderer);

/**
 * A volume over a ground: a plume of three overlapping puffs of smoke (a
 * vtkVolume of 48 x 48 x 36 samples, opacity rising with the density, its
 * colour warming from blue-grey to orange in the cores), the poles and a
 * floating sphere.
 */
void BuildSmokeScene(vtkRenderer* renderer);

/**
 * Builds a benchmark scene, a sweep scene, "street", "blocks", "glass",
 * "glass-opaque" (the glass scene whose translucent actors cast nothing: its
 * frame without transmittance maps), "smoke" (BuildSmokeScene), "smoke-opaque"
 * (its volume casting nothing), "contour" (BuildContourScene), "timesteps" (BuildTimeStepsScene),
 * "bigmesh" (BuildBigMeshScene) or "default"
 * (BuildDefaultScene) into an empty
 * renderer. Returns false with a one-line `error` for an unknown name or a
 * scene that cannot be built.
 */
bool BuildSceneByName(vtkRenderer* renderer, const std::string& name, std::string& error);

/** Every name BuildSceneByName builds. */
std::vector<std::string> SceneNames();

// --- light set-ups relative to the camera ----------------------------------------

/**
 * The light set-ups AddLightSetup understands: "overhead", "perpendicular",
 * "behind", "facing", "spot", "point", "wide-spot", "street-point",
 * "lamp-behind".
 */
std::vector<std::string> LightSetupNames();

/**
 * Set-ups whose light has a size (vtkAbstractShadowMapPass::LIGHT_SIZE), so
 * soft shadows: "soft-sun" (the perpendicular sun, 0.53 degrees across, the
 * real sun's), "soft-spot" and "soft-point" (the spot's and the point's
 * lights as spheres of radius 0.02 d). "soft-sun-D" also names the sun
 * D degrees across (D in (0, 30]), "soft-spot-P" and "soft-point-P" those
 * lamps with a radius of P% of d (P in (0, 25]), for a size's effect.
 */
std::vector<std::string> SizedLightSetupNames();

/** True for a name in SizedLightSetupNames(), a "soft-sun-D", "soft-spot-P"
 * or "soft-point-P". */
bool IsSizedLightSetup(const std::string& setup);

/** True for a name in LightSetupNames(), or a sized set-up (IsSizedLightSetup). */
bool IsLightSetup(const std::string& setup);

/** The kind of a set-up's light: "sun", "spot" or "point". */
std::string LightKindOfSetup(const std::string& setup);

/**
 * Replaces the renderer's lights by one scene light placed relative to the
 * active camera (call it after building the scene, with the scene's initial
 * camera). "Forward" is the camera's view direction projected onto the ground,
 * d the camera's distance to its focal point F. Suns (directional):
 *  - overhead:      4 degrees off straight down (so not axis-aligned), leaning
 *                   back and to the left of the view,
 *  - perpendicular: from the viewer's right, 35 degrees up: light travels at
 *                   right angles to the view,
 *  - behind:        from behind the viewer (25 degrees to the left of straight
 *                   behind, so that the shadows do not all hide behind their
 *                   casters), 35 degrees up: light travels the way the camera
 *                   looks,
 *  - facing:        from in front of the viewer, 35 degrees up, shining
 *                   towards the camera ("dueling frusta").
 * Positional lights:
 *  - spot:  45 degree cone (vtkLight's half-angle), 0.6 d back from F towards
 *           the camera along the ground and 0.8 d above F (so above and in
 *           front of the camera), aimed at F: it covers the near part of the
 *           view,
 *  - point: 180 degree cone, 0.3 d back from F along the ground and 0.5 d
 *           above F,
 *  - wide-spot: the spot's place and aim with a 75 degree cone (wider than
 *           one map holds: cube faces),
 *  - street-point: 180 degree cone at street level near the viewer, 0.75 d
 *           back from F along the ground, 0.1 d to the left and 0.08 d above
 *           F: its light reaches from the camera's feet to the far end of
 *           the view,
 *  - lamp-behind: 180 degree cone a little behind and high above the
 *           camera, 0.05 d back from it along the ground and 0.8 d above it:
 *           a lamp over the viewer's shoulder whose shadows run away down
 *           the view.
 * Returns false, changing nothing, for an unknown set-up.
 */
bool AddLightSetup(vtkRenderer* renderer, const std::string& setup);

// --- camera path -----------------------------------------------------------------

/**
 * Sets `camera` to frame `frame` of a smooth, deterministic path of
 * `frameCount` frames starting at `initial`: the camera moves straight along
 * the initial view direction by 20% of the initial focal distance in total
 * while turning left by `yawDegrees` (6 by default) about the world's +z axis
 * through itself,
 * both linearly in frame / (frameCount - 1). Frame 0 is `initial`; frames are
 * clamped to [0, frameCount - 1]. Everything else, the clipping range
 * included, is copied from `initial`. `initial` must be a separate copy of the
 * scene's initial camera, kept by the caller for the whole path:
 *
 *   vtkNew<vtkCamera> initial;
 *   initial->DeepCopy(renderer->GetActiveCamera());
 *   for (int f = 0; f < n; ++f)
 *     shadowscenes::SetCameraPathFrame(initial, renderer->GetActiveCamera(), f, n);
 */
void SetCameraPathFrame(vtkCamera* initial, vtkCamera* camera, int frame, int frameCount,
  double yawDegrees = 6.0);

} // namespace shadowscenes

#endif
