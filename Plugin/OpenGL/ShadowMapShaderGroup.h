// The maps of a pass come in groups, one per representation its lights use
// (vtkAbstractShadowMapPass::SetLightRepresentation). Every group's shadow
// code goes into the same mapper shaders: each group's names (vtkShadow...,
// VTK_SHADOW_...) get a suffix of its own, so that two representations'
// lookups, uniforms and #defines live side by side. Group 0's names have no
// suffix: a pass of one representation builds the shaders it always built.
// The casters' branches of all groups share one uniform, vtkShadowCasting,
// whose value says which group draws into its maps. Not a VTK class.
#ifndef ShadowMapShaderGroup_h
#define ShadowMapShaderGroup_h

#include <set>
#include <string>

namespace shadowmaps
{
/// The module's names (vtkShadow..., VTK_SHADOW_...) that `code` uses.
std::set<std::string> ShadowNamesIn(const std::string& code);

class ShaderGroup
{
public:
  explicit ShaderGroup(int index = 0);

  int Index() const { return this->GroupIndex; }

  /// What the group's names end with: nothing for group 0.
  const std::string& Suffix() const { return this->NameSuffix; }

  /// `name`, a uniform or function of the shadow code, as this group names it.
  std::string Name(const std::string& name) const { return name + this->NameSuffix; }

  /// The value of vtkShadowCasting that selects the group's casters' branch,
  /// and the one that selects its transmittance branch (translucent casters).
  int CastingValue() const { return 1 + 2 * this->GroupIndex; }
  int TransmittingValue() const { return 2 + 2 * this->GroupIndex; }

  /// Names every group shares: the mapper's shader held them before any
  /// group's code went in (the impostors', the camera's), or the casting
  /// selector. Rename leaves them alone.
  void ShareNames(const std::set<std::string>& names);

  /// `code` with each of the module's names made the group's, but the shared ones.
  std::string Rename(const std::string& code) const;

private:
  int GroupIndex = 0;
  std::string NameSuffix;
  std::set<std::string> Shared;
};
} // namespace shadowmaps

#endif
