#include "ShadowMapBuiltCode.h"

#include "ShadowMapPropParts.h"

#include "vtkAbstractMapper.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <iterator>
#include <set>

namespace shadowmaps
{
namespace
{
// Codes are kept by number; past this many, the numbers start anew (a renderer
// then builds once more).
constexpr std::size_t MostCodes = 256;
} // namespace

//------------------------------------------------------------------------------
void BuiltCode::Select(
  vtkRenderer* renderer, const std::string& code, const vtkRenderState* s, bool shadowed)
{
  if (!shadowed)
  {
    this->Forget(renderer);
    this->Current = nullptr;
    return;
  }
  RendererCode& current = this->Renderers[renderer];
  const int previous = current.Code;
  current.Renderer = renderer;
  current.Code = this->NumberOf(code);
  this->Current = &current;
  if (current.Code != previous || (this->AnyBuiltWithAnother() && this->BuiltWithAnother(s)) ||
    (this->RenderersDiffer() && this->SharedWithAnother(s)))
  {
    current.Rebuild.Modified();
  }
}

//------------------------------------------------------------------------------
void BuiltCode::Built(vtkAbstractMapper* mapper, vtkProp* prop)
{
  if (!this->Current)
  {
    return;
  }
  this->Record(mapper);
  vtkAbstractMapper* own = prop ? MapperOf(prop) : nullptr;
  if (own != mapper)
  {
    this->Record(own);
  }
}

//------------------------------------------------------------------------------
void BuiltCode::Record(vtkAbstractMapper* mapper)
{
  if (!mapper)
  {
    return;
  }
  auto record = this->Mappers.find(mapper);
  if (record == this->Mappers.end())
  {
    record = this->Mappers.emplace(mapper, std::make_pair(vtkWeakPointer<vtkObject>(mapper), 0)).first;
  }
  else if (!record->second.first)
  {
    record->second.first = mapper; // another mapper at a deleted one's address
  }
  if (record->second.second != this->Current->Code)
  {
    this->Count(record->second.second, -1);
    this->Count(this->Current->Code, +1);
    record->second.second = this->Current->Code;
  }
  if (this->Mappers.size() > 2 * this->MappersAtLastPurge + 64)
  {
    this->Purge();
  }
}

//------------------------------------------------------------------------------
void BuiltCode::Count(int code, int change)
{
  if (code == 0)
  {
    return; // a record not counted yet
  }
  long& count = this->RecordsOfCode[code];
  count += change;
  if (count == 0)
  {
    this->RecordsOfCode.erase(code);
  }
}

//------------------------------------------------------------------------------
void BuiltCode::Purge()
{
  for (auto it = this->Mappers.begin(); it != this->Mappers.end();)
  {
    if (it->second.first)
    {
      ++it;
      continue;
    }
    this->Count(it->second.second, -1);
    it = this->Mappers.erase(it);
  }
  this->MappersAtLastPurge = this->Mappers.size();
}

//------------------------------------------------------------------------------
bool BuiltCode::AnyBuiltWithAnother()
{
  const auto another = [this] {
    return std::any_of(this->RecordsOfCode.begin(), this->RecordsOfCode.end(),
      [this](const std::pair<const int, long>& codes) {
        return codes.first != this->Current->Code;
      });
  };
  if (!another())
  {
    return false;
  }
  this->Purge(); // the other code's mappers may all be gone
  return another();
}

//------------------------------------------------------------------------------
vtkMTimeType BuiltCode::RebuildTime() const
{
  return this->Current ? this->Current->Rebuild.GetMTime() : 0;
}

//------------------------------------------------------------------------------
void BuiltCode::Forget(vtkRenderer* renderer)
{
  auto found = this->Renderers.find(renderer);
  if (found != this->Renderers.end())
  {
    this->Current = this->Current == &found->second ? nullptr : this->Current;
    this->Renderers.erase(found);
  }
}

//------------------------------------------------------------------------------
void BuiltCode::Clear()
{
  this->Renderers.clear();
  this->Current = nullptr;
  this->Mappers.clear();
  this->MappersAtLastPurge = 0;
  this->RecordsOfCode.clear();
}

//------------------------------------------------------------------------------
int BuiltCode::NumberOf(const std::string& code)
{
  auto found = this->Numbers.find(code);
  if (found != this->Numbers.end())
  {
    return found->second;
  }
  if (this->Numbers.size() >= MostCodes)
  {
    this->Numbers.clear();
  }
  return this->Numbers[code] = this->NextNumber++;
}

//------------------------------------------------------------------------------
bool BuiltCode::RenderersDiffer()
{
  std::set<int> codes;
  for (auto it = this->Renderers.begin(); it != this->Renderers.end();)
  {
    if (!it->second.Renderer)
    {
      it = this->Renderers.erase(it); // deleted without releasing its maps
      continue;
    }
    if (it->second.Renderer->GetDraw())
    {
      codes.insert(it->second.Code);
    }
    ++it;
  }
  return codes.size() > 1;
}

//------------------------------------------------------------------------------
bool BuiltCode::SharedWithAnother(const vtkRenderState* s) const
{
  const auto otherCode = [this](vtkObject* consumer) {
    auto* renderer = vtkRenderer::SafeDownCast(consumer);
    auto found = this->Renderers.find(renderer);
    return renderer && renderer != this->Current->Renderer && renderer->GetDraw() &&
      found != this->Renderers.end() && found->second.Code != this->Current->Code;
  };
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    for (int c = 0; c < prop->GetNumberOfConsumers(); ++c)
    {
      if (otherCode(prop->GetConsumer(c)))
      {
        return true;
      }
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool BuiltCode::BuiltWithAnother(const vtkRenderState* s) const
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    bool another = false;
    ForEachPart(s->GetPropArray()[i], [&](vtkProp* part, vtkMatrix4x4*) {
      auto built = this->Mappers.find(MapperOf(part));
      another = another ||
        (built != this->Mappers.end() && built->second.first &&
          built->second.second != this->Current->Code);
    });
    if (another)
    {
      return true;
    }
  }
  return false;
}
} // namespace shadowmaps
