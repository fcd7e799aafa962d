#include "ShadowMapShaderGroup.h"

#include <cctype>
#include <cstring>

namespace shadowmaps
{
namespace
{
bool IsNameCharacter(char c)
{
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

bool StartsModuleName(const std::string& code, std::size_t at)
{
  for (const char* prefix : { "vtkShadow", "VTK_SHADOW" })
  {
    if (code.compare(at, std::strlen(prefix), prefix) == 0)
    {
      return true;
    }
  }
  return false;
}

// Calls `visit(begin, end)` for each whole word of `code` that is a module name.
template <typename Visit>
void ForEachModuleName(const std::string& code, Visit&& visit)
{
  std::size_t at = 0;
  while (at < code.size())
  {
    if (!IsNameCharacter(code[at]))
    {
      ++at;
      continue;
    }
    std::size_t end = at;
    while (end < code.size() && IsNameCharacter(code[end]))
    {
      ++end;
    }
    if (StartsModuleName(code, at))
    {
      visit(at, end);
    }
    at = end;
  }
}
} // namespace

//------------------------------------------------------------------------------
std::set<std::string> ShadowNamesIn(const std::string& code)
{
  std::set<std::string> names;
  ForEachModuleName(
    code, [&](std::size_t begin, std::size_t end) { names.insert(code.substr(begin, end - begin)); });
  return names;
}

//------------------------------------------------------------------------------
ShaderGroup::ShaderGroup(int index)
  : GroupIndex(index)
  , NameSuffix(index == 0 ? std::string() : "_g" + std::to_string(index))
{
  this->Shared.insert("vtkShadowCasting");
}

//------------------------------------------------------------------------------
void ShaderGroup::ShareNames(const std::set<std::string>& names)
{
  this->Shared.insert(names.begin(), names.end());
}

//------------------------------------------------------------------------------
std::string ShaderGroup::Rename(const std::string& code) const
{
  if (this->NameSuffix.empty())
  {
    return code;
  }
  std::string renamed;
  renamed.reserve(code.size() + code.size() / 8);
  std::size_t copied = 0;
  ForEachModuleName(code, [&](std::size_t begin, std::size_t end) {
    if (this->Shared.count(code.substr(begin, end - begin)) == 0)
    {
      renamed.append(code, copied, end - copied);
      renamed += this->NameSuffix;
      copied = end;
    }
  });
  renamed.append(code, copied, std::string::npos);
  return renamed;
}
} // namespace shadowmaps
