// What applications draw beside their data: axes, grids, labels, 3D text and
// widgets' representations neither cast nor receive shadows unless their keys
// say so, and props drawn unlit (lighting off, lines without normals) raise no
// warning about lights the pass could not patch.
#include "ShadowTestUtilities.h"

#include "vtkAbstractShadowMapPass.h"
#include "vtkAutomaticShadowMapPass.h"

#include "vtkActor.h"
#include "vtkAxesActor.h"
#include "vtkAxisActor.h"
#include "vtkAxisFollower.h"
#include "vtkBillboardTextActor3D.h"
#include "vtkBoxRepresentation.h"
#include "vtkCamera.h"
#include "vtkCubeAxesActor.h"
#include "vtkImageData.h"
#include "vtkImplicitPlaneRepresentation.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkOutlineFilter.h"
#include "vtkPolarAxesActor.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkTextActor3D.h"
#include "vtkTextProperty.h"
#include "vtkTransform.h"
#include "vtkVectorText.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

using namespace shadowtest;

namespace
{
// Low from the side: what stands above the ground throws long shadows on it.
const glm::dvec3 LowSun = glm::normalize(glm::dvec3(-1.0, 0.6, -0.7));

using AnnotationMaker = std::function<vtkSmartPointer<vtkProp>(TestScene&)>;

struct Annotation
{
  std::string Name;
  AnnotationMaker Make;
};

vtkSmartPointer<vtkProp> CubeAxes(TestScene& scene)
{
  auto axes = vtkSmartPointer<vtkCubeAxesActor>::New();
  axes->SetBounds(-6.0, 6.0, -6.0, 6.0, 0.0, 4.0);
  axes->SetCamera(scene.Renderer->GetActiveCamera());
  axes->DrawXGridlinesOn();
  axes->DrawYGridlinesOn();
  axes->DrawZGridlinesOn();
  axes->SetUse2DMode(false);
  return axes;
}

vtkSmartPointer<vtkProp> PolarAxes(TestScene& scene)
{
  auto axes = vtkSmartPointer<vtkPolarAxesActor>::New();
  axes->SetPole(0.0, -3.0, 3.0);
  axes->SetMaximumRadius(5.0);
  axes->SetCamera(scene.Renderer->GetActiveCamera());
  return axes;
}

vtkSmartPointer<vtkProp> OrientationAxes(TestScene&)
{
  auto axes = vtkSmartPointer<vtkAxesActor>::New();
  vtkNew<vtkTransform> placed;
  placed->Translate(-3.0, 3.0, 1.0);
  placed->Scale(3.0, 3.0, 3.0);
  axes->SetUserTransform(placed);
  axes->SetShaftTypeToCylinder();
  axes->SetCylinderRadius(0.1);
  return axes;
}

vtkSmartPointer<vtkProp> Text3D(TestScene&)
{
  auto text = vtkSmartPointer<vtkTextActor3D>::New();
  text->SetInput("Shadows");
  text->GetTextProperty()->SetFontSize(48);
  text->SetPosition(-4.0, -1.0, 3.0);
  text->SetOrientation(90.0, 0.0, 0.0);
  text->SetScale(0.06);
  return text;
}

vtkSmartPointer<vtkProp> BillboardText(TestScene&)
{
  auto text = vtkSmartPointer<vtkBillboardTextActor3D>::New();
  text->SetInput("Billboard label");
  text->GetTextProperty()->SetFontSize(36);
  text->GetTextProperty()->SetBackgroundColor(1.0, 1.0, 1.0);
  text->GetTextProperty()->SetBackgroundOpacity(1.0);
  text->SetPosition(-2.0, 2.0, 3.0);
  return text;
}

vtkSmartPointer<vtkProp> AxisLabel(TestScene& scene)
{
  // A label follows its axis, which the renderer holds (it is an annotation too).
  vtkNew<vtkAxisActor> axis;
  axis->SetPoint1(-6.0, -2.0, 2.0);
  axis->SetPoint2(6.0, -2.0, 2.0);
  axis->SetCamera(scene.Renderer->GetActiveCamera());
  scene.Renderer->AddViewProp(axis);
  vtkNew<vtkVectorText> letters;
  letters->SetText("X axis");
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(letters->GetOutputPort());
  auto label = vtkSmartPointer<vtkAxisFollower>::New();
  label->SetMapper(mapper);
  label->SetCamera(scene.Renderer->GetActiveCamera());
  label->SetAxis(axis);
  label->SetPosition(-5.0, -2.0, 2.5);
  label->SetScale(1.2);
  return label;
}

vtkSmartPointer<vtkProp> ImplicitPlaneWidget(TestScene& scene)
{
  auto plane = vtkSmartPointer<vtkImplicitPlaneRepresentation>::New();
  plane->SetRenderer(scene.Renderer);
  double bounds[6] = { -4.0, 4.0, -4.0, 4.0, 0.5, 4.0 };
  plane->PlaceWidget(bounds);
  plane->SetNormal(1.0, 0.0, 0.3);
  plane->SetOrigin(-1.0, 0.0, 2.0);
  return plane;
}

vtkSmartPointer<vtkProp> BoxWidget(TestScene& scene)
{
  auto box = vtkSmartPointer<vtkBoxRepresentation>::New();
  box->SetRenderer(scene.Renderer);
  double bounds[6] = { -3.0, 2.0, -5.0, -1.0, 1.0, 4.0 };
  box->PlaceWidget(bounds);
  box->SetHandleSize(10.0);
  return box;
}

std::vector<Annotation> EveryAnnotation()
{
  return { { "vtkCubeAxesActor", CubeAxes }, { "vtkPolarAxesActor", PolarAxes },
    { "vtkAxesActor", OrientationAxes }, { "vtkTextActor3D", Text3D },
    { "vtkBillboardTextActor3D", BillboardText }, { "vtkAxisFollower", AxisLabel },
    { "vtkImplicitPlaneRepresentation", ImplicitPlaneWidget },
    { "vtkBoxRepresentation", BoxWidget } };
}

void SetRoles(vtkProp* prop, int casts, int receives)
{
  if (!prop->GetPropertyKeys())
  {
    vtkNew<vtkInformation> keys;
    prop->SetPropertyKeys(keys);
  }
  for (const auto& role : { std::make_pair(vtkAbstractShadowMapPass::CASTS_SHADOWS(), casts),
         std::make_pair(vtkAbstractShadowMapPass::RECEIVES_SHADOWS(), receives) })
  {
    if (role.second < 0)
    {
      prop->GetPropertyKeys()->Remove(role.first);
    }
    else
    {
      prop->GetPropertyKeys()->Set(role.first, role.second);
    }
  }
}

// Pixels of `image` darker than in `reference` by more than 20 of 255 in luminance.
int DarkerPixels(vtkImageData* image, vtkImageData* reference)
{
  const auto a = RgbBytes(image);
  const auto b = RgbBytes(reference);
  int darker = 0;
  for (size_t i = 0; i + 2 < a.size() && a.size() == b.size(); i += 3)
  {
    const auto luminance = [](const std::vector<unsigned char>& rgb, size_t at) {
      return 0.2126 * rgb[at] + 0.7152 * rgb[at + 1] + 0.0722 * rgb[at + 2];
    };
    darker += luminance(a, i) < luminance(b, i) - 20.0 ? 1 : 0;
  }
  return darker;
}

struct AnnotatedScene
{
  TestScene Scene{ 360, 270 };
  vtkNew<vtkAutomaticShadowMapPass> Pass; // the default
  vtkSmartPointer<vtkProp> Prop;

  explicit AnnotatedScene(const Annotation& annotation)
  {
    this->Scene.SetSun(LowSun);
    this->Scene.Renderer->GetActiveCamera()->SetPosition(8.0, -10.0, 8.0);
    this->Scene.Renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 1.0);
    this->Scene.Renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
    this->Prop = annotation.Make(this->Scene);
    this->Scene.Renderer->AddViewProp(this->Prop);
    this->Scene.Renderer->ResetCameraClippingRange();
    this->Pass->SetResolution(1024);
    this->Scene.Renderer->SetPass(this->Pass);
  }

  vtkSmartPointer<vtkImageData> Frame(int casts, int receives)
  {
    SetRoles(this->Prop, casts, receives);
    return RenderAndCapture(this->Scene.Window);
  }
};
} // namespace

// Each annotation VTK applications show beside their data draws the frame it
// draws when its keys opt it out of both roles, and so casts on nothing and
// receives nothing; the sphere beside it still casts its shadow.
TEST(ShadowAnnotations, AnnotationsNeitherCastNorReceive)
{
  for (const Annotation& annotation : EveryAnnotation())
  {
    ErrorCounter errors;
    AnnotatedScene annotated(annotation);
    auto optedOut = annotated.Frame(0, 0);
    auto byDefault = annotated.Frame(-1, -1);
    EXPECT_EQ(DarkerPixels(byDefault, optedOut), 0)
      << annotation.Name << ": darker pixels than with the keys opting it out";
    EXPECT_TRUE(RgbBytes(byDefault) == RgbBytes(optedOut))
      << annotation.Name << " draws another frame than with the keys opting it out";
    // The darkest of a block: the annotation may hide a pixel of the shadow.
    EXPECT_LT(DarkestAround(annotated.Scene.Renderer, byDefault, GroundShadowOfSphereCenter(LowSun)),
      ShadowedBelow)
      << annotation.Name << ": the sphere beside it casts no shadow";
    EXPECT_EQ(errors.Errors() + errors.Warnings(), 0) << annotation.Name << ": " << errors.Text();
  }
}

// A key still makes an annotation cast (its parts, which draw with its keys,
// too); receiving stays off for them unless a key turns it on.
TEST(ShadowAnnotations, AKeyMakesAnAnnotationCast)
{
  for (const Annotation& annotation :
    { Annotation{ "vtkCubeAxesActor", CubeAxes }, Annotation{ "vtkBoxRepresentation", BoxWidget },
      Annotation{ "vtkAxesActor", OrientationAxes } })
  {
    ErrorCounter errors;
    AnnotatedScene annotated(annotation);
    auto byDefault = annotated.Frame(-1, -1);
    auto casting = annotated.Frame(1, -1);
    EXPECT_GT(DarkerPixels(casting, byDefault), 100)
      << annotation.Name << ": CASTS_SHADOWS = 1 cast no shadow";
    auto castingNotReceiving = annotated.Frame(1, 0);
    EXPECT_TRUE(RgbBytes(casting) == RgbBytes(castingNotReceiving))
      << annotation.Name << " received shadows, its keys not asking it to";
    EXPECT_EQ(errors.Errors(), 0) << annotation.Name << ": " << errors.Text();
  }
}

// Props drawn unlit (lighting off, PyVista's lighting=False; lines without
// normals, as an outline or cube axes draw them) are declared every light's
// colour by VTK's mapper but use none: the pass counts no light it could not
// patch and says nothing, receivers or not.
TEST(ShadowAnnotations, UnlitPropsRaiseNoWarning)
{
  ErrorCounter errors;
  TestScene scene(240, 180);
  scene.SetSun(LowSun);
  scene.Sphere->GetProperty()->LightingOff();
  vtkNew<vtkOutlineFilter> outline;
  outline->SetInputConnection(scene.SphereSource->GetOutputPort());
  AddSourceActor(scene.Renderer, outline);
  vtkSmartPointer<vtkProp> axes = CubeAxes(scene);
  scene.Renderer->AddViewProp(axes);
  SetRoles(axes, -1, 1);
  vtkNew<vtkAutomaticShadowMapPass> pass;
  scene.Renderer->SetPass(pass);
  auto image = RenderAndCapture(scene.Window);
  EXPECT_GT(pass->GetNumberOfShaderBuilds(), 3);
  EXPECT_EQ(pass->GetNumberOfUnpatchedReceiverLights(), 0);
  EXPECT_EQ(errors.Warnings() + errors.Errors(), 0) << errors.Text();
  EXPECT_LT(LuminanceAt(scene.Renderer, image, GroundShadowOfSphereCenter(LowSun)), ShadowedBelow)
    << "the unlit sphere casts no shadow";
}
