#include "vtkSIShadowRoleProperty.h"

#include "vtkAbstractShadowMapPass.h"
#include "vtkAlgorithm.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkObjectFactory.h"
#include "vtkPVXMLElement.h"
#include "vtkSMMessage.h"

#include <cstring>

vtkStandardNewMacro(vtkSIShadowRoleProperty);

//------------------------------------------------------------------------------
vtkSIShadowRoleProperty::vtkSIShadowRoleProperty() = default;

//------------------------------------------------------------------------------
vtkSIShadowRoleProperty::~vtkSIShadowRoleProperty() = default;

//------------------------------------------------------------------------------
vtkInformationIntegerKey* vtkSIShadowRoleProperty::KeyOf(const char* propertyName)
{
  if (propertyName && std::strcmp(propertyName, "CastsShadows") == 0)
  {
    return vtkAbstractShadowMapPass::CASTS_SHADOWS();
  }
  if (propertyName && std::strcmp(propertyName, "ReceivesShadows") == 0)
  {
    return vtkAbstractShadowMapPass::RECEIVES_SHADOWS();
  }
  return nullptr;
}

//------------------------------------------------------------------------------
bool vtkSIShadowRoleProperty::ReadXMLAttributes(vtkSIProxy* proxy, vtkPVXMLElement* element)
{
  if (!this->Superclass::ReadXMLAttributes(proxy, element))
  {
    return false;
  }
  if (!KeyOf(this->GetXMLName()))
  {
    vtkErrorMacro(<< "A shadow role property is named CastsShadows or ReceivesShadows, not "
                  << this->GetXMLName() << ".");
    return false;
  }
  int on = 1;
  element->GetScalarAttribute("default_values", &on);
  return this->Store(on);
}

//------------------------------------------------------------------------------
bool vtkSIShadowRoleProperty::Push(vtkSMMessage* message, int offset)
{
  const ProxyState_Property& property = message->GetExtension(ProxyState::property, offset);
  this->SaveValueToCache(message, offset);
  const Variant& value = property.value();
  return value.integer_size() < 1 || this->Store(value.integer(0));
}

//------------------------------------------------------------------------------
bool vtkSIShadowRoleProperty::Store(int on)
{
  auto* representation = vtkAlgorithm::SafeDownCast(this->GetVTKObject());
  if (!representation)
  {
    vtkErrorMacro(<< this->GetXMLName() << " needs a representation (a vtkAlgorithm).");
    return false;
  }
  vtkInformation* information = representation->GetInformation();
  vtkInformationIntegerKey* key = KeyOf(this->GetXMLName());
  // Not Modified(): that would run the representation's pipeline again; the
  // view reads the value every render.
  information->Set(key, on != 0 ? 1 : 0);
  return true;
}

//------------------------------------------------------------------------------
void vtkSIShadowRoleProperty::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
