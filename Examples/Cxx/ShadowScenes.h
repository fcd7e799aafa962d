// Scenes and lights shared by the vtkshadows program, the tests and the
// benchmarks. All scenes use +z as the up axis; models loaded from files are
// not rotated.
#ifndef ShadowScenes_h
#define ShadowScenes_h

#include <string>

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
 * case-insensitive), puts it on a ground plane four times its size and frames
 * the camera on it from an elevated three-quarter view. On failure (unknown
 * extension, unreadable file, no geometry) returns false, leaves the renderer
 * untouched and sets `error` to a one-line message.
 */
bool BuildFileScene(vtkRenderer* renderer, const std::string& path, std::string& error);

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

} // namespace shadowscenes

#endif
