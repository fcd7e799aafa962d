#include "vtkPVShadowRenderView.h"

#include "vtkAbstractShadowMapPass.h"
#include "vtkAutomaticShadowMapPass.h"
#include "vtkCascadedShadowMapViews.h"
#include "vtkCompositeRepresentation.h"
#include "vtkDepthShadowMapPass.h"
#include "vtkDualDepthShadowMapPass.h"
#include "vtkGeometryRepresentation.h"
#include "vtkPVLODVolume.h"
#include "vtkVolumeRepresentation.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightKit.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVDefaultPass.h"
#include "vtkPVLODActor.h"
#include "vtkPVShadowMapExchange.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVarianceShadowMapPass.h"
#include "vtkWarpedShadowMapViews.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkPVShadowRenderView);
vtkInformationKeyMacro(vtkPVShadowRenderView, SIZED_BY_VIEW, Integer);

namespace
{
template <typename T>
T Clamped(vtkObject* self, const char* name, T value, T lowest, T highest)
{
  if (!std::isfinite(static_cast<double>(value)))
  {
    return value; // the module's setter refuses it, with its warning
  }
  const T clamped = std::min(std::max(value, lowest), highest);
  if (clamped != value)
  {
    vtkWarningWithObjectMacro(self, << name << " " << value << " is outside [" << lowest << ", "
                                    << highest << "]; using " << clamped << ".");
  }
  return clamped;
}
} // namespace

//------------------------------------------------------------------------------
vtkPVShadowRenderView::vtkPVShadowRenderView()
  : Passes{ vtkDepthShadowMapPass::New(), vtkDualDepthShadowMapPass::New(),
    vtkVarianceShadowMapPass::New() }
  , AutomaticPass(vtkAutomaticShadowMapPass::New())
  , WarpedViews(vtkWarpedShadowMapViews::New())
  , CascadedViews(vtkCascadedShadowMapViews::New())
  , ScenePass(vtkPVDefaultPass::New())
  , Exchange(vtkPVShadowMapExchange::New())
{
  for (vtkAbstractShadowMapPass* pass : this->AllPasses())
  {
    // The renderer's own steps (SSAO, hidden lines, translucency, volumes)
    // render the scene, as in ParaView's plain render view.
    pass->SetDelegatePass(this->ScenePass);
    pass->SetResolution(this->ShadowMapResolution);
  }
  this->MarkLightKitLights();
  this->UsePass();
}

//------------------------------------------------------------------------------
vtkPVShadowRenderView::~vtkPVShadowRenderView()
{
  // Before the pass leaves the renderer: the window's release then no longer
  // reaches it, and the maps' texture array frees nothing on its own.
  for (vtkAbstractShadowMapPass* pass : this->AllPasses())
  {
    this->ReleasePass(pass);
  }
  this->SynchronizedRenderers->SetRenderPass(nullptr);
  for (vtkAbstractShadowMapPass* pass : this->AllPasses())
  {
    pass->Delete();
  }
  this->WarpedViews->Delete();
  this->CascadedViews->Delete();
  this->ScenePass->Delete();
  this->Exchange->Delete();
}

//------------------------------------------------------------------------------
vtkAbstractShadowMapPass* vtkPVShadowRenderView::GetShadowPass()
{
  if (this->ShadowViews == AUTOMATIC)
  {
    return this->AutomaticPass;
  }
  return this->Passes[this->ShadowStorage];
}

//------------------------------------------------------------------------------
std::array<vtkAbstractShadowMapPass*, 4> vtkPVShadowRenderView::AllPasses()
{
  return { this->Passes[DEPTH], this->Passes[DUAL_DEPTH], this->Passes[MOMENTS],
    this->AutomaticPass };
}

//------------------------------------------------------------------------------
int vtkPVShadowRenderView::GetNumberOfShadowedLights()
{
  return this->GetShadowPass()->GetNumberOfShadowedLights();
}

//------------------------------------------------------------------------------
bool vtkPVShadowRenderView::GetAnimationFrame()
{
  return this->AnimationFrame;
}

//------------------------------------------------------------------------------
vtkDepthShadowMapPass* vtkPVShadowRenderView::DepthPass(int storage)
{
  return static_cast<vtkDepthShadowMapPass*>(this->Passes[storage]);
}

//------------------------------------------------------------------------------
vtkVarianceShadowMapPass* vtkPVShadowRenderView::MomentsPass()
{
  return static_cast<vtkVarianceShadowMapPass*>(this->Passes[MOMENTS]);
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowFilter(int filter)
{
  filter = Clamped(this, "ShadowFilter", filter, static_cast<int>(vtkDepthShadowMapPass::HARD),
    static_cast<int>(vtkDepthShadowMapPass::POISSON));
  for (int storage : { DEPTH, DUAL_DEPTH })
  {
    this->DepthPass(storage)->SetFilter(filter);
  }
  this->AutomaticPass->SetFilter(filter); // its own dual-depth maps
}

//------------------------------------------------------------------------------
int vtkPVShadowRenderView::GetShadowFilter()
{
  return this->DepthPass(DEPTH)->GetFilter();
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowFilterRadius(double texels)
{
  texels = Clamped(this, "ShadowFilterRadius", texels, 0.5, 16.0);
  for (int storage : { DEPTH, DUAL_DEPTH })
  {
    this->DepthPass(storage)->SetFilterRadius(texels);
  }
  this->AutomaticPass->SetFilterRadius(texels);
}

//------------------------------------------------------------------------------
double vtkPVShadowRenderView::GetShadowFilterRadius()
{
  return this->DepthPass(DEPTH)->GetFilterRadius();
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowConstantBias(double bias)
{
  this->DepthPass(DEPTH)->SetConstantBias(Clamped(this, "ShadowConstantBias", bias, 0.0, 10000.0));
}

//------------------------------------------------------------------------------
double vtkPVShadowRenderView::GetShadowConstantBias()
{
  return this->DepthPass(DEPTH)->GetConstantBias();
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowSlopeScaledBias(double bias)
{
  this->DepthPass(DEPTH)->SetSlopeScaledBias(Clamped(this, "ShadowSlopeScaledBias", bias, 0.0, 100.0));
}

//------------------------------------------------------------------------------
double vtkPVShadowRenderView::GetShadowSlopeScaledBias()
{
  return this->DepthPass(DEPTH)->GetSlopeScaledBias();
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetMomentsBlurRadius(double texels)
{
  this->MomentsPass()->SetBlurRadius(Clamped(this, "MomentsBlurRadius", texels, 0.0, 16.0));
}

//------------------------------------------------------------------------------
double vtkPVShadowRenderView::GetMomentsBlurRadius()
{
  return this->MomentsPass()->GetBlurRadius();
}

//------------------------------------------------------------------------------
double vtkPVShadowRenderView::GetBytesCombined()
{
  return this->Exchange->GetBytesReduced();
}

//------------------------------------------------------------------------------
double vtkPVShadowRenderView::GetSecondsCombining()
{
  return this->Exchange->GetSecondsReducing();
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::ReleasePass(vtkAbstractShadowMapPass* pass)
{
  vtkRenderWindow* window = this->GetRenderWindow();
  if (window && !window->GetNeverRendered())
  {
    window->MakeCurrent();
    pass->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
bool vtkPVShadowRenderView::CombinesAcrossRanks()
{
  // Ranks that share one camera and split the data combine their maps. CAVE and
  // tile displays, whose ranks see through cameras or tiles of their own (and
  // CAVEs replicate the data), would combine different views.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller && controller->GetNumberOfProcesses() > 1 && !this->InCaveDisplayMode() &&
    !this->InTileDisplayMode();
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::Update()
{
  this->Superclass::Update();
  if (this->CombinesAcrossRanks())
  {
    // IceT skips the render of a rank whose geometry is empty; the maps'
    // combination waits for every rank.
    this->RenderEmptyImages = true;
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::Render(bool interactive, bool skip_rendering)
{
  vtkAbstractShadowMapPass* pass = this->GetShadowPass();
  // One rank keeps the per-layer re-rendering the exchange gives up.
  const bool combine = this->CombinesAcrossRanks();
  pass->SetExchange(combine ? this->Exchange : nullptr);
  const bool global = combine && this->GeometryBounds.IsValid();
  if (global)
  {
    double bounds[6];
    this->GeometryBounds.GetBounds(bounds);
    pass->SetSceneBounds(bounds);
  }
  pass->SetUseSceneBounds(global);
  this->ApplyShadowRoles();
  this->ApplyLightSizes();
  // Every rank has the same view time, so all keep views alike. The renders
  // after a new time (a screenshot's, a saved animation's capture) stay
  // animation frames, or they would draw the maps once more at each frame.
  const double time = this->GetViewTime();
  const bool newTime = !std::isnan(this->RenderedViewTime) && time != this->RenderedViewTime;
  this->AnimationFrame = !interactive && (newTime || this->AnimationFrame);
  this->RenderedViewTime = time;
  pass->SetAnimationKeepsViews(this->AnimationFrame);
  this->Superclass::Render(interactive, skip_rendering);
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::ApplyLightSizes()
{
  vtkLightCollection* lights = this->GetRenderer()->GetLights();
  lights->InitTraversal();
  for (vtkLight* light = lights->GetNextItem(); light; light = lights->GetNextItem())
  {
    vtkInformation* information = light->GetInformation();
    if (information->Has(vtkAbstractShadowMapPass::LIGHT_SIZE()) &&
      !information->Has(SIZED_BY_VIEW()))
    {
      continue; // sized by the user (a script): theirs
    }
    // Without LIGHT_SIZE, the size read is the light's own Radius, if any.
    information->Remove(vtkAbstractShadowMapPass::LIGHT_SIZE());
    information->Remove(SIZED_BY_VIEW());
    const double size = light->GetPositional() ? this->LampRadius : this->SunDiameter;
    if (size > 0.0 && !(vtkAbstractShadowMapPass::GetLightSize(light) > 0.0))
    {
      information->Set(vtkAbstractShadowMapPass::LIGHT_SIZE(), size);
      information->Set(SIZED_BY_VIEW(), 1);
    }
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::ApplyShadowRoles()
{
  for (int i = 0; i < this->GetNumberOfRepresentations(); ++i)
  {
    vtkDataRepresentation* representation = this->GetRepresentation(i);
    auto* composite = vtkCompositeRepresentation::SafeDownCast(representation);
    vtkDataRepresentation* active = composite ? composite->GetActiveRepresentation() : representation;
    auto* surface = vtkGeometryRepresentation::SafeDownCast(active);
    auto* volume = vtkVolumeRepresentation::SafeDownCast(active);
    vtkProp* prop = surface ? static_cast<vtkProp*>(surface->GetActor())
      : volume              ? static_cast<vtkProp*>(volume->GetActor())
                            : nullptr;
    if (!prop)
    {
      continue;
    }
    vtkInformation* roles = representation->GetInformation();
    for (vtkInformationIntegerKey* key :
      { vtkAbstractShadowMapPass::CASTS_SHADOWS(), vtkAbstractShadowMapPass::RECEIVES_SHADOWS() })
    {
      if (!roles->Has(key))
      {
        continue;
      }
      if (!prop->GetPropertyKeys())
      {
        vtkNew<vtkInformation> keys;
        prop->SetPropertyKeys(keys);
      }
      prop->GetPropertyKeys()->Set(key, roles->Get(key));
    }
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetSunDiameter(double degrees)
{
  if (!std::isfinite(degrees))
  {
    vtkWarningMacro(<< "SunDiameter " << degrees << " is not finite; keeping " << this->SunDiameter << ".");
    return;
  }
  degrees = Clamped(this, "SunDiameter", degrees, 0.0, 30.0);
  if (degrees != this->SunDiameter)
  {
    this->SunDiameter = degrees;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetLampRadius(double radius)
{
  if (!std::isfinite(radius))
  {
    vtkWarningMacro(<< "LampRadius " << radius << " is not finite; keeping " << this->LampRadius << ".");
    return;
  }
  radius = Clamped(this, "LampRadius", radius, 0.0, std::numeric_limits<double>::max());
  if (radius != this->LampRadius)
  {
    this->LampRadius = radius;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::UsePass()
{
  if (this->ShadowViews == AUTOMATIC)
  {
    // The storage passes' representations carry the view's filter, bias and
    // blur; the automatic pass's own is dual depth, which needs no offset.
    const bool dual = this->ShadowStorage == DUAL_DEPTH;
    vtkAbstractShadowMapPass* storage = this->Passes[this->ShadowStorage];
    this->AutomaticPass->SetRepresentation(dual ? nullptr : storage->GetRepresentation());
    this->AutomaticPass->SetNormalOffset(dual ? 0.0 : storage->GetNormalOffset());
  }
  else if (this->ShadowViews == CASCADES)
  {
    this->GetShadowPass()->SetViews(this->CascadedViews);
  }
  else
  {
    const int modes[] = { vtkWarpedShadowMapViews::UNIFORM, vtkWarpedShadowMapViews::LISPSM,
      vtkWarpedShadowMapViews::TSM, vtkWarpedShadowMapViews::PSM, vtkWarpedShadowMapViews::GMNPR };
    this->WarpedViews->SetWarpMode(modes[this->ShadowViews]);
    this->GetShadowPass()->SetViews(this->WarpedViews);
  }
  this->GetShadowPass()->SetAnalysisView(this->ShadowAnalysisView);
  this->SynchronizedRenderers->SetRenderPass(this->GetShadowPass());
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::MarkLightKitLights()
{
  // vtkLightKit adds its head light, then its key, fill and back lights; the key
  // light is the first that is not a headlight (headlights never cast).
  vtkNew<vtkRenderer> kitLights;
  this->LightKit->AddLightsToRenderer(kitLights);
  vtkLightCollection* lights = kitLights->GetLights();
  lights->InitTraversal();
  bool keyFound = false;
  for (vtkLight* light = lights->GetNextItem(); light; light = lights->GetNextItem())
  {
    const bool isKey = !keyFound && !light->LightTypeIsHeadlight();
    keyFound = keyFound || isKey;
    light->GetInformation()->Set(
      vtkAbstractShadowMapPass::CASTS_SHADOWS(), isKey && this->KeyLightShadows ? 1 : 0);
    light->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowViews(int views)
{
  views = Clamped(this, "ShadowViews", views, static_cast<int>(UNIFORM), static_cast<int>(AUTOMATIC));
  if (views != this->ShadowViews)
  {
    vtkAbstractShadowMapPass* before = this->GetShadowPass();
    this->ShadowViews = views;
    if (this->GetShadowPass() != before)
    {
      // As for a storage change: the pass left behind frees its maps now.
      this->ReleasePass(before);
    }
    this->UsePass();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowStorage(int storage)
{
  storage =
    Clamped(this, "ShadowStorage", storage, static_cast<int>(DEPTH), static_cast<int>(MOMENTS));
  if (storage != this->ShadowStorage)
  {
    // The pass left behind frees its maps now: a later release of the window
    // reaches only the pass in use.
    this->ReleasePass(this->GetShadowPass());
    this->ShadowStorage = storage;
    this->UsePass();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowMapResolution(int resolution)
{
  resolution = Clamped(this, "ShadowMapResolution", resolution, 64, 16384);
  if (resolution != this->ShadowMapResolution)
  {
    this->ShadowMapResolution = resolution;
    for (vtkAbstractShadowMapPass* pass : this->AllPasses())
    {
      pass->SetResolution(resolution);
    }
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetNumberOfCascades(int count)
{
  this->CascadedViews->SetNumberOfCascades(count);
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkPVShadowRenderView::GetNumberOfCascades()
{
  return this->CascadedViews->GetNumberOfCascades();
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowAnalysisView(int view)
{
  view = Clamped(this, "ShadowAnalysisView", view, static_cast<int>(vtkAbstractShadowMapPass::NO_ANALYSIS),
    static_cast<int>(vtkAbstractShadowMapPass::CHOSEN_VIEWS));
  if (view != this->ShadowAnalysisView)
  {
    this->ShadowAnalysisView = view;
    this->GetShadowPass()->SetAnalysisView(view);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetKeyLightShadows(bool on)
{
  if (on != this->KeyLightShadows)
  {
    this->KeyLightShadows = on;
    this->MarkLightKitLights();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShadowViews: " << this->ShadowViews << "\n";
  os << indent << "ShadowStorage: " << this->ShadowStorage << "\n";
  os << indent << "ShadowMapResolution: " << this->ShadowMapResolution << "\n";
  os << indent << "NumberOfCascades: " << this->CascadedViews->GetNumberOfCascades() << "\n";
  os << indent << "ShadowAnalysisView: " << this->ShadowAnalysisView << "\n";
  os << indent << "KeyLightShadows: " << this->KeyLightShadows << "\n";
  os << indent << "ShadowFilter: " << this->GetShadowFilter() << "\n";
  os << indent << "ShadowFilterRadius: " << this->GetShadowFilterRadius() << "\n";
  os << indent << "ShadowConstantBias: " << this->GetShadowConstantBias() << "\n";
  os << indent << "ShadowSlopeScaledBias: " << this->GetShadowSlopeScaledBias() << "\n";
  os << indent << "MomentsBlurRadius: " << this->GetMomentsBlurRadius() << "\n";
  os << indent << "SunDiameter: " << this->SunDiameter << "\n";
  os << indent << "LampRadius: " << this->LampRadius << "\n";
}
