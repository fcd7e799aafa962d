#ifndef ShadowMapLayerDrawing_h
#define ShadowMapLayerDrawing_h

#include "ShadowMapLight.h"
#include "ShadowMapProgramUniforms.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpaquePass.h"
#include "vtkSmartPointer.h"
#include "vtkTranslucentPass.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

class vtkOpenGLRenderer;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderPass;
class vtkWindow;

namespace shadowmaps
{
struct RendererMaps;

/// Draws layers of a renderer's maps: a layer's casters, seen from its light
/// view, into the layer, then its translucent casters and volumes into its
/// transmittance map, one GPU step per function. Which layers to draw, and with
/// which casters, is the pass's and MapUpdates' decision; this only draws them.
/// It owns the light camera and the passes the casters draw through.
class LayerDrawing
{
public:
  LayerDrawing();
  ~LayerDrawing();

  /// What one update's layers share.
  struct Update
  {
    vtkOpenGLRenderer* Renderer = nullptr;
    RendererMaps* Maps = nullptr;
    const ShadowFrame* Frame = nullptr;
    ProgramUniforms* Programs = nullptr;
    /// The casters' settings (their LargestPointSize is filled in by BeginUpdate).
    CastingSettings Casting;
    /// The casters keep their light depths beside the maps (Combination::NearestLightDepths).
    bool KeepsLightDepths = false;
    /// The texture unit of depth peeling's first-pass depths.
    int PeelUnit = -1;
    /// Has the props join the pass's render passes, so that they draw
    /// through their shaders' casters' branch.
    std::function<void(vtkProp* const*, int)> JoinCasters;
  };

  /// The renderer looks through the light camera until EndUpdate.
  void BeginUpdate(const Update& update);
  void EndUpdate();

  /// Draws `casters` into layer `layer`, view `v` of `light`. False, with
  /// `error`, when the GL fails; `bound` says whether the layer was bound
  /// (and so its content replaced) before that.
  bool Draw(const ShadowLight& light, std::size_t v, int layer, std::vector<vtkProp*>& casters,
    bool& bound, std::string& error);

  /// The casters drawn since BeginUpdate, every pass over a layer counted.
  int GetDraws() const { return this->Draws; }

  /// What kept some volume from casting, each warned once while it lasts.
  std::vector<std::string> TakeWarnings();

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  /// The largest point size the context draws (impostors' sprites), asked once
  /// per context: a query may wait for the GL's thread.
  float LargestPointSize();
  void ClearLayer(bool linearDepths);
  int DrawCasters(std::vector<vtkProp*>& casters, vtkRenderPass* pass);
  bool DrawCastersIntoView(const LightView& view, std::vector<vtkProp*>& casters,
    bool linearDepths);
  bool PeelSecondSurface(int layer, std::vector<vtkProp*>& casters, std::string& error);
  bool DrawTransmittance(int layer, const ShadowLight& light, const LightView& view,
    std::vector<vtkProp*>& casters, std::string& error);
  int MarchVolumes(vtkOpenGLRenderWindow* window, const ShadowLight& light, const LightView& view,
    const std::vector<vtkProp*>& casters);

  Update Current;
  vtkSmartPointer<vtkCamera> SceneCamera;
  vtkNew<vtkCamera> LightCamera;
  vtkNew<vtkMatrix4x4> LightProjection;
  vtkNew<vtkOpaquePass> OpaquePass;
  vtkNew<vtkTranslucentPass> TranslucentPass;
  int Draws = 0;
  float PointSizeLimit = 0.0f;
  std::string WarnedVolumeDraw;
  std::vector<std::string> Warnings;
};
} // namespace shadowmaps

#endif
