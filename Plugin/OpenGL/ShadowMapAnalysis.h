// The analysis views of a shadow-map pass (vtkAbstractShadowMapPass::AnalysisView):
// the receiver code that recolours the scene (visibility, texel density,
// partition) and the SHADOW_MAP view that draws a light's maps over the frame.
#ifndef ShadowMapAnalysis_h
#define ShadowMapAnalysis_h

#include <array>
#include <memory>
#include <string>
#include <vector>

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkWindow;

namespace shadowmaps
{
struct ReceiverCode;
struct ShadowLight;
class TextureArray;

/// The analysis view that colours a light's kind of views
/// (vtkAbstractShadowMapPass::CHOSEN_VIEWS).
constexpr int ChosenViewsAnalysis = 5;

/// Fills code's analysis members for the receiver analysis view `view` of light
/// `light`: VTK_SHADOW_ANALYSIS of vtkShadowMapsAnalysisFS (1 visibility, 2
/// texel density, 4 partition, 5 chosen views; vtkAbstractShadowMapPass's
/// AnalysisViewType values). `viewsKind`: the light's views
/// (vtkShadowMapViews::GetKindName), coloured by ViewsKindColor in view 5.
/// Leaves them empty for 0 and for a light index out of range.
void AddAnalysisReceiverCode(int view, int light, const std::string& viewsKind,
  const std::vector<ShadowLight>& lights, ReceiverCode& code);

/// The colour of the CHOSEN_VIEWS view for a kind of views (the legend in
/// vtkAbstractShadowMapPass.h); white for a kind it does not know.
std::array<float, 3> ViewsKindColor(const std::string& viewsKind);

/// The SHADOW_MAP view: one light's maps tiled over the viewport, depths as grey.
class MapView
{
public:
  MapView();
  ~MapView();
  MapView(const MapView&) = delete;
  MapView& operator=(const MapView&) = delete;

  /// Draws the maps of `light`, bound to texture unit `mapUnit`; `twoSurfaces`:
  /// maps of two surfaces' depths (SecondDepthMethod), both side by side;
  /// `warpExponent` c > 0: the first value stored is exp(c (2 d - 1)) of the
  /// depth d shown (MapStorage::WarpExponent). False when the view's shader
  /// does not compile.
  bool Render(vtkOpenGLRenderWindow* window, TextureArray& maps, int mapUnit,
    const ShadowLight& light, bool twoSurfaces, double warpExponent = 0.0);
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
};
} // namespace shadowmaps

#endif
