#include "ShadowMapGroups.h"

#include "ShadowMapImpostors.h"
#include "ShadowMapSceneReading.h"
#include "ShadowMapShaderGroup.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapExchange.h"
#include "vtkShadowMapRepresentation.h"
#include "vtkVolume.h"

#include <algorithm>
#include <utility>

namespace shadowmaps
{
namespace
{
vtkOpenGLRenderWindow* WindowOf(vtkOpenGLRenderer* renderer)
{
  return static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
}
} // namespace

//------------------------------------------------------------------------------
void MapGroups::SelectRenderer(vtkOpenGLRenderer* renderer)
{
  for (Group& group : this->Groups)
  {
    group.Update->SelectRenderer(renderer);
  }
}

//------------------------------------------------------------------------------
std::vector<vtkShadowMapRepresentation*> MapGroups::RepresentationsInUse(
  vtkOpenGLRenderer* renderer, const FrameSettings& settings,
  const RepresentationOf& representationOf)
{
  int skipped = 0;
  std::vector<vtkLight*> clamped;
  const std::vector<ShadowLight> lights = CollectShadowedLights(renderer, settings.Casts,
    settings.LightSize, settings.MaximumShadowedLights, skipped, clamped);
  std::vector<vtkShadowMapRepresentation*> used;
  for (const ShadowLight& light : lights)
  {
    vtkShadowMapRepresentation* representation = representationOf(light.Light);
    if (std::find(used.begin(), used.end(), representation) == used.end())
    {
      used.push_back(representation);
    }
  }
  if (used.empty())
  {
    used.push_back(settings.Representation);
  }
  return used;
}

//------------------------------------------------------------------------------
void MapGroups::FormGroups(const std::vector<vtkShadowMapRepresentation*>& used,
  const std::vector<vtkShadowMapRepresentation*>& assigned, vtkOpenGLRenderWindow* window)
{
  const auto isIn = [](const std::vector<vtkShadowMapRepresentation*>& list,
                      vtkShadowMapRepresentation* representation) {
    return std::find(list.begin(), list.end(), representation) != list.end();
  };
  bool changed = false;
  for (auto group = this->Groups.begin(); group != this->Groups.end();)
  {
    if (isIn(assigned, group->Representation))
    {
      ++group;
      continue;
    }
    this->Release(*group, window);
    group = this->Groups.erase(group);
    changed = true;
  }
  for (vtkShadowMapRepresentation* representation : used)
  {
    if (std::none_of(this->Groups.begin(), this->Groups.end(),
          [representation](const Group& group) { return group.Representation == representation; }))
    {
      Group group;
      group.Representation = representation;
      group.Update = std::make_unique<FrameUpdate>();
      this->Groups.push_back(std::move(group));
      changed = true;
    }
  }
  if (changed)
  {
    // Each group's code has its place's names: the shaders are made anew.
    this->GroupsTime.Modified();
  }
}

//------------------------------------------------------------------------------
bool MapGroups::Prepare(vtkOpenGLRenderer* renderer, const vtkRenderState* s,
  const FrameSettings& settings, const RepresentationOf& representationOf,
  const std::vector<vtkShadowMapRepresentation*>& assigned)
{
  vtkOpenGLRenderWindow* window = WindowOf(renderer);
  this->FormGroups(RepresentationsInUse(renderer, settings, representationOf), assigned, window);
  this->SelectRenderer(renderer);
  const bool alone = this->Groups.size() == 1;
  for (std::size_t g = 0; g < this->Groups.size(); ++g)
  {
    Group& group = this->Groups[g];
    group.Settings = settings;
    group.Settings.Representation = group.Representation;
    group.Settings.Group = static_cast<int>(g);
    group.Settings.AmongGroups = !alone;
    if (!alone)
    {
      group.Settings.Shadows = [representationOf, representation = group.Representation.Get()](
                                 vtkLight* light) { return representationOf(light) == representation; };
    }
    group.Ready = group.Update->Prepare(renderer, s, group.Settings);
  }
  const bool shadowed = std::any_of(this->Groups.begin(), this->Groups.end(),
    [](const Group& group) { return !group.Update->Lights().empty(); });
  const std::string code = this->CodeKey();
  this->Built.Select(renderer, code, s, shadowed);
  // Asked in every frame, shadowed or not: with several groups, every process
  // makes the same collective call.
  if (!this->CodeCompiles(code, window, settings.Exchange))
  {
    // Every group still renders its step, failing: the other processes wait
    // for its answer.
    for (Group& group : this->Groups)
    {
      group.Update->Abandon(alone
          ? "the shadow shader code does not compile (see the shader error above; a "
            "representation's GLSL?)"
          : "the shadow shader code of the lights' representations does not compile together "
            "(see the shader error above)");
    }
  }
  bool any = false;
  for (Group& group : this->Groups)
  {
    group.Ready = group.Ready && group.Update->Render(renderer);
    any = any || group.Ready;
  }
  return any;
}

//------------------------------------------------------------------------------
bool MapGroups::CodeCompiles(
  const std::string& key, vtkOpenGLRenderWindow* window, vtkShadowMapExchange* exchange)
{
  auto checked = this->CheckedCodes.find(key);
  if (checked == this->CheckedCodes.end())
  {
    if (this->CheckedCodes.size() >= 16)
    {
      this->CheckedCodes.clear();
    }
    checked = this->CheckedCodes.emplace(key, PassShaders::Compiles(window, this->ShaderCode())).first;
  }
  const bool compiles = checked->second;
  // Every process renders its groups' maps, or none does.
  return exchange && this->Groups.size() >= 2 ? !exchange->AnyOf(!compiles) : compiles;
}

//------------------------------------------------------------------------------
std::string MapGroups::CodeKey() const
{
  std::string key;
  for (const Group& group : this->Groups)
  {
    key += group.Update->Shaders().GetKey();
    key += '\n';
  }
  return key;
}

//------------------------------------------------------------------------------
void MapGroups::BindForReceivers(vtkOpenGLRenderer* renderer)
{
  for (Group& group : this->Groups)
  {
    if (group.Ready)
    {
      group.Update->BindForReceivers(renderer);
    }
  }
}

//------------------------------------------------------------------------------
void MapGroups::Fail(const std::string& error, vtkWindow* context)
{
  for (Group& group : this->Groups)
  {
    group.Update->Fail(error, context);
    group.Ready = false;
  }
}

//------------------------------------------------------------------------------
std::vector<std::string> MapGroups::TakeWarnings()
{
  std::vector<std::string> warnings;
  for (Group& group : this->Groups)
  {
    for (std::string& warning : group.Update->TakeWarnings())
    {
      // A failure every group met is warned once.
      if (std::find(warnings.begin(), warnings.end(), warning) == warnings.end())
      {
        warnings.push_back(std::move(warning));
      }
    }
  }
  return warnings;
}

//------------------------------------------------------------------------------
FrameStatistics MapGroups::Statistics() const
{
  FrameStatistics all;
  for (const Group& group : this->Groups)
  {
    if (group.Update->Lights().empty() && this->Groups.size() > 1)
    {
      continue; // what it counted is of a frame it had lights in
    }
    const FrameStatistics& one = group.Update->Statistics();
    all.ShadowedLights += one.ShadowedLights;
    all.Layers += one.Layers;
    all.NonFiniteViews += one.NonFiniteViews;
    all.Updates += one.Updates;
    all.CasterDraws += one.CasterDraws;
    all.RenderedLayers += one.RenderedLayers;
    all.CasterPassesPerLayer = std::max(all.CasterPassesPerLayer, one.CasterPassesPerLayer);
    all.Resolution = std::max(all.Resolution, one.Resolution);
    all.Steps.Add(one.Steps);
  }
  return all;
}

//------------------------------------------------------------------------------
void MapGroups::ClearFrameStatistics()
{
  for (Group& group : this->Groups)
  {
    group.Update->ClearFrameStatistics();
  }
}

//------------------------------------------------------------------------------
int MapGroups::Count() const
{
  return static_cast<int>(std::count_if(this->Groups.begin(), this->Groups.end(),
    [](const Group& group) { return !group.Update->Lights().empty(); }));
}

//------------------------------------------------------------------------------
std::vector<GroupCode> MapGroups::ShaderCode() const
{
  std::vector<GroupCode> code;
  for (const Group& group : this->Groups)
  {
    code.push_back(group.Update->ShaderCode());
  }
  return code;
}

//------------------------------------------------------------------------------
vtkMTimeType MapGroups::ShaderKeyTime() const
{
  return std::max(this->GroupsTime.GetMTime(), this->Built.RebuildTime());
}

//------------------------------------------------------------------------------
void MapGroups::SetProgramUniforms(
  vtkShaderProgram* program, vtkProp* prop, bool active, double normalOffset)
{
  auto casting = std::find_if(this->Groups.begin(), this->Groups.end(),
    [](const Group& group) { return group.Update->CastingState() != nullptr; });
  if (casting != this->Groups.end())
  {
    casting->Update->CastingState()->UseProgramPointSize(ImpostorShader::IsSized(program));
    for (Group& group : this->Groups)
    {
      if (&group != &*casting && !group.Update->Shaders().Empty())
      {
        group.Update->Programs().WhileOthersCast(
          program, group.Update->Textures().Units(), group.Representation);
      }
    }
    casting->Update->Programs().Casting(
      program, casting->Update->Textures().Units(), casting->Representation);
    return;
  }
  for (std::size_t g = 0; g < this->Groups.size(); ++g)
  {
    Group& group = this->Groups[g];
    FrameUpdate& update = *group.Update;
    if (update.Shaders().Empty() && this->Groups.size() > 1)
    {
      continue; // nothing of the group's is in the programs
    }
    const ReceiverTextureUnits units = update.Textures().Units();
    if (!active || !group.Ready)
    {
      update.Programs().DrawnWithoutThePass(program, units, group.Representation);
      continue;
    }
    update.Programs().Receiving(
      program, update.Maps(), units, update.Frame().Resolution, normalOffset, group.Representation);
    const std::vector<float>& shares = update.LightShares();
    if (vtkVolume::SafeDownCast(prop) && !shares.empty())
    {
      program->SetUniform1fv(ShaderGroup(static_cast<int>(g)).Name("vtkShadowVolumeLightShares").c_str(),
        static_cast<int>(shares.size()), shares.data());
    }
  }
}

//------------------------------------------------------------------------------
FrameUpdate* MapGroups::AnalysedGroup(int& light) const
{
  for (const Group& group : this->Groups)
  {
    const int analysed = group.Update->AnalysedLight();
    if (group.Ready && analysed >= 0 &&
      analysed < static_cast<int>(group.Update->Lights().size()))
    {
      light = group.Update->AnalysedLight();
      return group.Update.get();
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
void MapGroups::EndFrame()
{
  for (Group& group : this->Groups)
  {
    group.Update->Programs().EndFrame();
  }
}

//------------------------------------------------------------------------------
void MapGroups::ReleaseTextureUnits(vtkOpenGLRenderWindow* window)
{
  for (Group& group : this->Groups)
  {
    group.Update->Textures().Release(window, group.Representation);
  }
}

//------------------------------------------------------------------------------
bool MapGroups::HoldsMapsOf(vtkRenderer* renderer) const
{
  return std::any_of(this->Groups.begin(), this->Groups.end(),
    [renderer](const Group& group) { return group.Update->HoldsMapsOf(renderer); });
}

//------------------------------------------------------------------------------
bool MapGroups::HoldsNoMaps() const
{
  return std::all_of(this->Groups.begin(), this->Groups.end(),
    [](const Group& group) { return group.Update->HoldsNoMaps(); });
}

//------------------------------------------------------------------------------
std::size_t MapGroups::MemoryBytes() const
{
  std::size_t bytes = 0;
  for (const Group& group : this->Groups)
  {
    bytes += group.Update->MemoryBytes();
  }
  return bytes;
}

//------------------------------------------------------------------------------
void MapGroups::ReleaseMapsOf(vtkRenderer* renderer, vtkOpenGLRenderWindow* window)
{
  for (Group& group : this->Groups)
  {
    group.Update->ReleaseMapsOf(renderer, window);
  }
  this->ForgetCodeOf(renderer);
}

//------------------------------------------------------------------------------
void MapGroups::Release(Group& group, vtkWindow* window)
{
  group.Update->Textures().Release(static_cast<vtkOpenGLRenderWindow*>(window), group.Representation);
  group.Update->ReleaseGraphicsResources(window);
  // A representation no light uses any more (unpinned) holds nothing either;
  // one still in use elsewhere makes its resources again.
  group.Representation->ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void MapGroups::ReleaseGraphicsResources(vtkWindow* window)
{
  for (Group& group : this->Groups)
  {
    group.Update->ReleaseGraphicsResources(window);
    group.Representation->ReleaseGraphicsResources(window);
  }
  this->Built.Clear();
}
} // namespace shadowmaps
