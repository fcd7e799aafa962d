/**
 * @class   vtkSIShadowRoleProperty
 * @brief   The server side of a representation's "Casts Shadows" and
 *          "Receives Shadows" properties.
 *
 * ParaView's representations have no setter for the shadow module's per-prop
 * keys, and a plugin cannot add one to them. The plugin adds the two
 * properties to the surface representations with this class as their
 * si_class: it keeps the value on the representation object itself, in its
 * algorithm information, under vtkAbstractShadowMapPass::CASTS_SHADOWS or
 * RECEIVES_SHADOWS (by the property's name), on every process that has the
 * representation. vtkPVShadowRenderView copies them to the prop each
 * representation renders (vtkPVShadowRenderView::ApplyShadowRoles).
 */
#ifndef vtkSIShadowRoleProperty_h
#define vtkSIShadowRoleProperty_h

#include "vtkParaViewShadowViewModule.h" // For export macro
#include "vtkSIProperty.h"

class vtkInformation;
class vtkInformationIntegerKey;

class VTKPARAVIEWSHADOWVIEW_EXPORT vtkSIShadowRoleProperty : public vtkSIProperty
{
public:
  static vtkSIShadowRoleProperty* New();
  vtkTypeMacro(vtkSIShadowRoleProperty, vtkSIProperty);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The module's key a role property of this name sets; nullptr for other names. */
  static vtkInformationIntegerKey* KeyOf(const char* propertyName);

protected:
  vtkSIShadowRoleProperty();
  ~vtkSIShadowRoleProperty() override;

  bool ReadXMLAttributes(vtkSIProxy* proxy, vtkPVXMLElement* element) override;
  bool Push(vtkSMMessage* message, int offset) override;

private:
  vtkSIShadowRoleProperty(const vtkSIShadowRoleProperty&) = delete;
  void operator=(const vtkSIShadowRoleProperty&) = delete;

  /** Keeps `on` on the representation object; false when there is none. */
  bool Store(int on);
};

#endif
