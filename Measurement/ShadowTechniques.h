// The techniques the benchmark and the sweep measure, by name, and the
// captures both take of a view: shared by ShadowBench and ShadowSweep.
#ifndef ShadowTechniques_h
#define ShadowTechniques_h

#include "ShadowOracle.h"

#include <vtkSmartPointer.h>

#include <cstdint>
#include <string>
#include <vector>

class vtkAbstractShadowMapPass;
class vtkLight;
class vtkRenderPass;
class vtkRenderWindow;
class vtkRenderer;
class vtkShadowMapPass;

namespace shadowbench
{

/// One technique set up on a renderer: the pass and what the metrics need of it.
struct TechniqueInstance
{
  vtkSmartPointer<vtkRenderPass> Pass; // null: no shadows
  vtkAbstractShadowMapPass* Ours = nullptr;
  vtkShadowMapPass* VTK = nullptr;
  int Resolution = 0;
};

/// VTK's own shadow maps, set up as in VTK's TestShadowMapPass (camera pass,
/// then the baker and the shadow pass in sequence); `shadows`, if given,
/// receives the vtkShadowMapPass.
vtkSmartPointer<vtkRenderPass> MakeVTKShadowMapPass(
  unsigned int resolution, vtkShadowMapPass** shadows = nullptr);

/// "none", "vtk" (VTK's vtkShadowMapPass at its default 1024^2), "vtk-equal"
/// (the same at the memory of "uniform"), "uniform" (vtkWarpedShadowMapPass,
/// focused uniform map, 2x2 PCF), "psm", "lispsm", "tsm" and "gmnpr" (the same
/// pass warped), "csm", "csm-tight" and "csm-lispsm" (vtkCascadedShadowMapPass,
/// four cascades of half the resolution: stable, tight, tight with LiSPSM),
/// "second-depth", "midpoint" and "dual" (vtkDualDepthShadowMapPass on the
/// uniform technique's views, every bias 0, AUTO layer method), "dual-minblend"
/// and "dual-peel" (dual with a forced layer method), "dual-offset<K>" for K
/// in 0.5, 1, 4, 8 (dual with DualOffset K texels), and the uniform map's
/// bias sweep "uniform-bias<B>" for B in 0, 1, 4, 16, 64 (default normal
/// offset) and "uniform-bias<B>-offset0" (normal offset 0), and the pairs
/// "<representation>+<views>": depth, dual or evsm4 on uniform, psm, psm-cube,
/// lispsm, tsm, gmnpr, csm or csm-lispsm views (e.g. "dual+csm"), and "auto"
/// (vtkAutomaticShadowMapPass) and "auto-cost6" (the same, CostBudget 6).
std::vector<std::string> TechniqueNames();

/// The techniques a benchmark measures unless told: TechniqueNames() without
/// the dual pass's forced layer methods and the bias sweep.
std::vector<std::string> DefaultTechniqueNames();

/// One of each family, the ones that differ most: the references, the uniform
/// map, LiSPSM, cascades, second-depth and moments, and the automatic pass
/// (vtkshadows analyze).
std::vector<std::string> QuickTechniqueNames();

/// True for a name in TechniqueNames().
bool IsTechnique(const std::string& name);

/// False, with a one-line `error`, if a name is not a technique
/// (TechniqueNames()) or not a light set-up (shadowscenes::LightSetupNames()).
bool CheckTechniquesAndSetups(const std::vector<std::string>& techniques,
  const std::vector<std::string>& setups, std::string& error);

/// `techniques` with "none" and "vtk" first where missing: frame times are
/// ratios to them.
std::vector<std::string> WithReferenceTechniques(std::vector<std::string> techniques);

/// The technique `name` at `resolution` for a light set-up (VTK's pass at
/// equal memory needs to know whether the light is a point light).
TechniqueInstance MakeTechnique(const std::string& name, bool pointLight, int resolution);

/// Memory of the technique's maps after a render, in MiB.
double MemoryMiB(const TechniqueInstance& technique);

/// White, purely diffuse materials: the ratio of a render with shadows to one
/// without is then the light's shadow factor at every pixel.
void UseMeasurementMaterials(vtkRenderer* renderer);

/// The frame last rendered, RGB, row 0 at the bottom.
std::vector<std::uint8_t> CaptureRGB(vtkRenderWindow* window);

/// Window depths in [0, 1] of the first width x height pixels.
std::vector<float> CaptureDepth(vtkRenderWindow* window, int width, int height);

/// Creates `directory` if needed; false with a one-line `error` if it is not
/// a directory afterwards.
bool MakeOutputDirectory(const std::string& directory, std::string& error);

/// Writes RGB bytes as a PNG; false if it cannot.
bool WritePNG(const std::vector<std::uint8_t>& rgb, int width, int height, const std::string& path);

/// value with `digits` decimals; "n/a" for NaN (the tables' number format).
std::string FormatNumber(double value, int digits = 2);

/// The oracle's view of the frame `renderer` last rendered into `window`
/// (width x height pixels): one primary ray per pixel, pixels where the
/// rasterised depth disagrees (silhouettes, skipped geometry) or that the
/// render without shadows, `unshadowedRgb` (CaptureRGB of that frame, the one
/// the techniques' factors divide by), leaves black (no factor to read) made
/// invalid.
shadoworacle::Surface VisibleSurface(const shadoworacle::Oracle& oracle, vtkRenderer* renderer,
  vtkRenderWindow* window, int width, int height, const std::vector<std::uint8_t>& unshadowedRgb);

/// The renderer's first light (nullptr if it has none).
vtkLight* FirstLight(vtkRenderer* renderer);

/// While alive, takes every VTK error and warning instead of the output
/// window that was there (restored on destruction), counting and keeping them.
class MessageLog
{
public:
  MessageLog();
  ~MessageLog();
  MessageLog(const MessageLog&) = delete;
  MessageLog& operator=(const MessageLog&) = delete;
  int Errors() const;
  int Warnings() const;
  std::string Text() const;

private:
  struct Impl;
  Impl* Pimpl;
};

} // namespace shadowbench

#endif
