// vtkshadows: renders a scene with shadows and writes a PNG, or measures the
// techniques against ray-traced truth.
//
//   vtkshadows render [options]        see PrintUsage() below
//   vtkshadows gallery [options]
//   vtkshadows bench [options]
//   vtkshadows analyze FILE [options]
//   vtkshadows sweep [options]
//   vtkshadows speed [options]
//
// Every error prints one line "vtkshadows: error: ..." on stderr and exits
// with status 2.
#include "ShadowBench.h"
#include "ShadowGallery.h"
#include "ShadowSpeed.h"
#include "ShadowScenes.h"
#include "ShadowSweep.h"
#include "ShadowTechniques.h"

#include "vtkDepthShadowMapPass.h"

#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{

constexpr int ExitUsageError = 2;

struct Options
{
  std::string command; // "render", "gallery", "bench", "analyze", "sweep" or "speed"
  bool help = false;
  shadowbench::Options bench = shadowbench::DefaultOptions();
  shadowgallery::Options gallery; // its techniques, size, resolution and folder: bench's
  shadowsweep::Options sweep;
  bool interactiveMoving = true; // speed: moving frames rendered as a drag
  bool movingData = false;       // speed: moving frames play the scene's data
  bool movie = false;            // speed: still moving frames, views kept
  std::string scene = "default";
  std::string light = "sun";
  double azimuth = 60.0;
  double elevation = 45.0;
  std::string technique = "auto"; // a shadowbench::TechniqueNames() name
  int resolution = 2048;
  int filter = vtkDepthShadowMapPass::PCF_2X2;
  int kernelSize = 3; // N of pcf:N
  int width = 800;
  int height = 600;
  std::string output = "vtkshadows.png";
};

/** What every command does, on one screen. */
void PrintOverview(std::ostream& out)
{
  out <<
    "usage: vtkshadows COMMAND [options]\n"
    "\n"
    "commands:\n"
    "  render    renders a scene with shadows into a PNG and prints its path\n"
    "  gallery   a few scenes drawn by VTK's pass, the default and each technique\n"
    "            beside the ray-cast truth, with error maps, figures and a page\n"
    "  bench     every technique against ray-traced truth on the benchmark scenes:\n"
    "            a table, error maps, charts and a technique per light kind\n"
    "  analyze   the same for a model FILE (.obj .ply .stl .vtp .gltf .glb) on a\n"
    "            ground, a quick answer (about a minute and a half, 2 cores)\n"
    "  sweep     random scenes, cameras and lights: each technique's distribution\n"
    "  speed     first, steady and moving frame times beside no shadows and VTK's\n"
    "\n"
    "examples:\n"
    "  vtkshadows render --technique auto -o shadows.png\n"
    "  vtkshadows analyze model.stl --out analysis\n"
    "  vtkshadows gallery --out gallery\n"
    "\n"
    "vtkshadows COMMAND --help lists a command's options (help COMMAND: the same);\n"
    "docs/GUIDE.md explains the techniques and their settings.\n";
}

const char* RenderHelp()
{
  return "usage: vtkshadows render [options]\n\n"
         "Renders a scene with shadows and writes a PNG; prints the PNG's absolute path.\n\n"
         "options of render:\n"
         "  --scene default|FILE     built-in scene or a model (.obj .ply .stl .vtp .gltf .glb)\n"
         "                           [default]\n"
         "  --up x|y|z|-x|-y|-z      the model's up axis [glTF: y; a model standing on a\n"
         "                           coordinate plane: that axis; OBJ, PLY: y; STL, VTP: z]\n"
         "  --light sun|spot|point   light kind [sun]\n"
         "  --azimuth A              light azimuth in degrees, from +x towards +y [60]\n"
         "  --elevation E            light elevation above the ground, -90..90 [45]\n"
         "  --technique NAME         auto: vtkAutomaticShadowMapPass (each light's views chosen\n"
         "                           from its situation, dual-depth maps); uniform, psm,\n"
         "                           lispsm, tsm, gmnpr: vtkWarpedShadowMapPass's\n"
         "                           warp modes (psm-cube, psm-single: PSMCubeMap always,\n"
         "                           never); csm, csm-tight, csm-lispsm: vtkCascadedShadowMapPass\n"
         "                           at half the resolution; second-depth, midpoint, dual:\n"
         "                           vtkDualDepthShadowMapPass, no bias; vsm, evsm2, evsm4, msm,\n"
         "                           esm: vtkVarianceShadowMapPass; vtk, vtk-equal: VTK's\n"
         "                           vtkShadowMapPass; none: no shadows [auto]\n"
         "  --resolution N           shadow map size in texels, 64..16384 [2048]\n"
         "  --filter hard|pcf2x2|pcf:N|poisson\n"
         "                           shadow filter, N of pcf:N in 2..7 [pcf2x2]\n"
         "  --size WxH               image size, each 16..8192 [800x600]\n"
         "  -o, --output FILE        output PNG [./vtkshadows.png]\n"
         "  -h, --help               this help\n";
}

const char* BenchIntro()
{
  return "usage: vtkshadows bench [options]\n"
         "       vtkshadows analyze FILE [options]\n\n"
         "bench measures every technique on the benchmark scenes against ray-traced truth;\n"
         "prints a markdown table and which technique to use per light kind (the most accurate\n"
         "within 1.25x the uniform map's frame), writes error maps, charts, results.md,\n"
         "results.csv and recommendation.json. analyze does the same for a model file on a\n"
         "ground, by default a quick answer.\n\n";
}

const char* BenchOptionsHelp()
{
  return
         "options of bench and analyze (lists are comma-separated; analyze's defaults in\n"
         "braces):\n"
         "  --scenes LIST            bench only: outdoor,paraview,model [these three],\n"
         "                           glass (translucent casters: transmittance errors),\n"
         "                           smoke (a volume: transmittance errors)\n"
         "  --up x|y|z|-x|-y|-z      analyze only: the model's up axis, as for render\n"
         "  --setups LIST|all|soft   overhead,perpendicular,behind,facing,spot,point,\n"
         "                           wide-spot,street-point,lamp-behind [these nine];\n"
         "                           sized lights (soft shadows, measured against\n"
         "                           ray-traced area lights): soft-sun (0.53\n"
         "                           degrees), soft-spot, soft-point (radius 0.02 of\n"
         "                           the camera's distance), soft-sun-D (the sun D\n"
         "                           degrees across, up to 30), soft-spot-P,\n"
         "                           soft-point-P (radius P% of the camera's\n"
         "                           distance, up to 25); soft: soft-sun, soft-spot,\n"
         "                           soft-point; all: the nine and those three\n"
         "                           {perpendicular,spot,point}\n"
         "  --techniques LIST|all    none,vtk,vtk-equal,uniform,psm,lispsm,tsm,gmnpr,csm,\n"
         "                           csm-tight,csm-lispsm,second-depth,midpoint,dual,evsm4\n"
         "                           [all of these] {uniform,lispsm,csm,second-depth,evsm4,auto}\n"
         "                           (auto: vtkAutomaticShadowMapPass, its choice reported;\n"
         "                           auto-cost6: the same with CostBudget 6; auto-full-drag:\n"
         "                           with InteractiveResolutionScale 1;\n"
         "                           R+V: representation R of depth, dual, evsm4 on views V of\n"
         "                           uniform, psm, psm-cube, lispsm, lispsm-lloyd, tsm, gmnpr,\n"
         "                           csm, csm-lispsm)\n"
         "                           (csm: 4 cascades of N/2, stable, tight, or tight with LiSPSM\n"
         "                           in each cascade and in a spot's tiled map); also dual-minblend,\n"
         "                           dual-peel (forced layer method), dual-offsetK (K: 0.5,1,4,8\n"
         "                           texels of DualOffset) and the uniform map's bias\n"
         "                           sweep uniform-biasB, uniform-biasB-offset0 (B: 0,1,4,16,64);\n"
         "                           psm-cube, psm-single (PSM's cube map for every light, none);\n"
         "                           the moment maps vsm, evsm2, msm, esm and the uniform map's\n"
         "                           softer filters pcf3 (3 x 3) and poisson (radius 1.5); the\n"
         "                           moment maps' sweep vsm-bleed0, vsm-bleed0.4, evsm4-bleed0,\n"
         "                           evsm4-half, evsm4-blur0, evsm4-blur2, evsm4-blur4, msm-bleed0,\n"
         "                           evsm4-samples4, msm-biasX (X: 0.0001, 0.001), msm-half\n"
         "                           (16 bits), msm-half-biasX; the fixed filters that sized\n"
         "                           lights' soft shadows are measured against (soft shadows\n"
         "                           off): poisson-rR (32 taps, R: 1,2,4,8,16 texels) and\n"
         "                           evsm4-hard-blurB (B: 0,1,2,4,8,16 texels);\n"
         "                           none and vtk are always measured (frame-time references)\n"
         "  --technique NAME         one technique (with none and vtk)\n"
         "  --resolution N           map size of this project's techniques [2048]\n"
         "  --size WxH               image size [640x360]\n"
         "  --flicker-frames N       frames of the camera path, 0 or 2..600 [60] {12}\n"
         "  --flicker-setups LIST    set-ups measured along the path [perpendicular]\n"
         "  --flicker-yaw DEG        how far the camera turns along the path, 0..180 [6]\n"
         "  --timed-frames N         frames per frame-time figure, 1..100 [8] {3}\n"
         "  --out DIR                output directory [./bench]\n";
}

const char* SpeedHelp()
{
  return "usage: vtkshadows speed [options]\n\n"
         "First, steady and moving (orbiting) frame times of none, vtk and techniques,\n"
         "interleaved in one process, at --resolution and at 64; prints a markdown table,\n"
         "writes speed.md, speed.csv and frames.csv (every timed frame).\n\n"
         "options of speed: those of bench but the flicker options, with\n"
         "  --scenes LIST            outdoor,paraview,model,street (225 actors),\n"
         "                           blocks (2,026 actors), glass (translucent casters),\n"
         "                           glass-opaque (the same casting opaque shadows only),\n"
         "                           smoke (a volume), smoke-opaque (its volume not casting),\n"
         "                           contour (an isosurface of 780k triangles whose value\n"
         "                           --moving data changes every frame), timesteps (six\n"
         "                           such surfaces made once, a step a frame, as a reader of\n"
         "                           a file series plays them), bigmesh (that isosurface\n"
         "                           still, each triangle split in four: 3.3M)\n"
         "                           [outdoor,paraview,model,street]\n"
         "  --setups LIST            [perpendicular,spot]\n"
         "  --techniques LIST        [uniform,lispsm,csm] (none and vtk always measured)\n"
         "  --size WxH               [960x540]\n"
         "  --moving interactive|still|movie|data\n"
         "                           moving frames rendered as a user's drag (the window's\n"
         "                           desired update rate at an interactor's 15), as a\n"
         "                           scripted animation (the still rate), as one with our\n"
         "                           passes' AnimationKeepsViews on (movie), or as a time\n"
         "                           series playing (the camera still, the scene's data\n"
         "                           changed before each frame's clock starts) [interactive]\n"
         "  --out DIR                [./speed]\n";
}

const char* SweepHelp()
{
  return "usage: vtkshadows sweep [options]\n\n"
         "Measures techniques against ray-traced truth on random scenes, cameras and\n"
         "lights; prints each technique's distribution, worst cases and flagged cases.\n\n"
         "options of sweep:\n"
         "  --cases N                random cases, 1..1000000 [200]\n"
         "  --seed S                 seed of the sweep, 0..2^64-1 [1]\n"
         "  --first-case N           start at the sweep's case N, 0..1000000 (a sweep run\n"
         "                           in parts) [0]\n"
         "  --techniques LIST|all    as for bench, without none\n"
         "                           [uniform,psm,lispsm,tsm,gmnpr,csm,csm-tight,csm-lispsm]\n"
         "  --resolution N           map size [2048]\n"
         "  --size WxH               base image size, each case scales each side by 0.5..1.5\n"
         "                           [192x144]\n"
         "  --min-counted N          counted pixels a case needs to enter the distributions [300]\n"
         "  --counted-only yes|no    render the techniques only in cases with that many\n"
         "                           counted pixels [no]\n"
         "  --replay SEED            render the one case of that seed (printed by a sweep),\n"
         "                           with its frames and error maps\n"
         "  --lights hard|sized      sized: every light gets a size drawn from its case's\n"
         "                           seed (suns 0.25..8 degrees, lamps 0.2..5% of the\n"
         "                           scene), measured against ray-traced area lights [hard]\n"
         "  --out DIR                output directory [./sweep]\n";
}

const char* GalleryHelp()
{
  return "usage: vtkshadows gallery [options]\n\n"
         "Draws each case with VTK's pass, the default and each technique beside the\n"
         "ray-cast truth; writes per case <scene>-<set-up>-truth.png and one PNG per\n"
         "technique (the frame beside its error map: light leaks red, false shadows\n"
         "blue), gallery.csv, overview.png (VTK's pass, the default and the truth for\n"
         "the first three cases) and a markdown page; prints the page's path.\n\n"
         "options of gallery:\n"
         "  --out DIR                the pictures and gallery.csv [./gallery]\n"
         "  --page FILE              the markdown page, its image links relative to its\n"
         "                           folder [DIR/gallery.md]\n"
         "  --cases LIST             scene:set-up pairs, scenes as speed's, set-ups as\n"
         "                           bench's [street:perpendicular,outdoor:perpendicular,\n"
         "                           model:spot,outdoor:street-point,glass:perpendicular,\n"
         "                           smoke:perpendicular,paraview:soft-spot-3]\n"
         "  --techniques LIST        as bench's [vtk,auto,uniform,lispsm,csm,dual,evsm4]\n"
         "  --size WxH               each picture's size [400x225]\n"
         "  --resolution N           map size of this project's techniques [2048]\n";
}

/** The help of `command`, or the overview for none or an unknown one. */
void PrintUsage(std::ostream& out, const std::string& command = std::string())
{
  if (command == "bench" || command == "analyze")
  {
    out << BenchIntro() << BenchOptionsHelp();
    return;
  }
  const std::map<std::string, const char*> helps = { { "render", RenderHelp() },
    { "speed", SpeedHelp() }, { "sweep", SweepHelp() }, { "gallery", GalleryHelp() } };
  const auto help = helps.find(command);
  if (help == helps.end())
  {
    PrintOverview(out);
    return;
  }
  out << help->second;
  if (command == "speed")
  {
    out << "\n" << BenchOptionsHelp();
  }
}

// --- value parsing -----------------------------------------------------------

/** Whole-string integer; no sign games, no trailing characters. */
bool ParseInt(const std::string& text, int& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  const long parsed = std::strtol(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || parsed < -2147483647L || parsed > 2147483647L)
  {
    return false;
  }
  value = static_cast<int>(parsed);
  return true;
}

/** Whole-string finite floating-point number. */
bool ParseDouble(const std::string& text, double& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  const double parsed = std::strtod(text.c_str(), &end);
  if (errno != 0 || *end != '\0' || !std::isfinite(parsed))
  {
    return false;
  }
  value = parsed;
  return true;
}

// Each option parser returns an empty string on success, else the error.

std::string ParseScene(const std::string& value, Options& options)
{
  if (value.empty())
  {
    return "scene file name is empty";
  }
  options.scene = value;
  return {};
}

std::string ParseUp(const std::string& value, Options& options)
{
  if (!shadowscenes::ParseUpAxis(value, options.bench.Up))
  {
    return "unknown up axis '" + value + "' (expected x, y, z, -x, -y or -z)";
  }
  return {};
}

std::string ParseLight(const std::string& value, Options& options)
{
  if (!shadowscenes::IsLightKind(value))
  {
    return "unknown light '" + value + "' (expected sun, spot or point)";
  }
  options.light = value;
  return {};
}

std::string ParseAzimuth(const std::string& value, Options& options)
{
  if (!ParseDouble(value, options.azimuth))
  {
    return "azimuth '" + value + "' is not a number";
  }
  return {};
}

std::string ParseElevation(const std::string& value, Options& options)
{
  double elevation = 0.0;
  if (!ParseDouble(value, elevation) || elevation < -90.0 || elevation > 90.0)
  {
    return "elevation '" + value + "' is not a number in -90..90";
  }
  options.elevation = elevation;
  return {};
}

// "unknown technique 'NAME' (expected a, b or c)", naming every technique.
std::string UnknownTechnique(const std::string& name)
{
  const auto names = shadowbench::TechniqueNames();
  std::string expected;
  for (size_t i = 0; i < names.size(); ++i)
  {
    expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  }
  return "unknown technique '" + name + "' (expected " + expected + ")";
}

std::string ParseTechnique(const std::string& value, Options& options)
{
  if (!shadowbench::IsTechnique(value))
  {
    return UnknownTechnique(value);
  }
  options.technique = value;
  return {};
}

std::string ParseResolution(const std::string& value, Options& options)
{
  int resolution = 0;
  if (!ParseInt(value, resolution) || resolution < 64 || resolution > 16384)
  {
    return "resolution '" + value + "' is not an integer in 64..16384";
  }
  options.resolution = resolution;
  return {};
}

std::string ParseFilter(const std::string& value, Options& options)
{
  static const std::map<std::string, int> namedFilters = { { "hard", vtkDepthShadowMapPass::HARD },
    { "pcf2x2", vtkDepthShadowMapPass::PCF_2X2 }, { "poisson", vtkDepthShadowMapPass::POISSON } };
  const auto found = namedFilters.find(value);
  if (found != namedFilters.end())
  {
    options.filter = found->second;
    return {};
  }
  const std::string pcfPrefix = "pcf:";
  if (value.compare(0, pcfPrefix.size(), pcfPrefix) == 0)
  {
    int kernelSize = 0;
    if (!ParseInt(value.substr(pcfPrefix.size()), kernelSize) || kernelSize < 2 ||
      kernelSize > 7)
    {
      return "filter '" + value + "': N of pcf:N must be an integer in 2..7";
    }
    options.filter = vtkDepthShadowMapPass::PCF_NXN;
    options.kernelSize = kernelSize;
    return {};
  }
  return "unknown filter '" + value + "' (expected hard, pcf2x2, pcf:N or poisson)";
}

std::string ParseSize(const std::string& value, Options& options)
{
  const std::string malformed = "size '" + value + "' is not WxH with W and H in 16..8192";
  const std::size_t separator = value.find('x');
  if (separator == std::string::npos)
  {
    return malformed;
  }
  int width = 0;
  int height = 0;
  if (!ParseInt(value.substr(0, separator), width) ||
    !ParseInt(value.substr(separator + 1), height) || width < 16 || width > 8192 ||
    height < 16 || height > 8192)
  {
    return malformed;
  }
  options.width = width;
  options.height = height;
  return {};
}

std::string ParseOutput(const std::string& value, Options& options)
{
  if (value.empty())
  {
    return "output file name is empty";
  }
  options.output = value;
  return {};
}

std::vector<std::string> SplitList(const std::string& value)
{
  std::vector<std::string> items;
  std::stringstream stream(value);
  for (std::string item; std::getline(stream, item, ',');)
  {
    if (!item.empty())
    {
      items.push_back(item);
    }
  }
  return items;
}

std::string ParseScenes(const std::string& value, Options& options)
{
  auto names = shadowscenes::BenchmarkSceneNames();
  names.push_back("glass");
  names.push_back("smoke");
  for (const std::string& scene : SplitList(value))
  {
    if (std::find(names.begin(), names.end(), scene) == names.end())
    {
      return "unknown scene '" + scene + "' (expected outdoor, paraview, model, glass or smoke)";
    }
  }
  options.bench.Scenes = SplitList(value);
  return options.bench.Scenes.empty() ? "no scene given" : std::string();
}

std::string ParseSpeedScenes(const std::string& value, Options& options)
{
  auto names = shadowscenes::BenchmarkSceneNames();
  names.push_back("street");
  names.push_back("blocks");
  names.push_back("glass");
  names.push_back("glass-opaque");
  names.push_back("smoke");
  names.push_back("smoke-opaque");
  names.push_back("contour");
  names.push_back("timesteps");
  names.push_back("bigmesh");
  for (const std::string& scene : SplitList(value))
  {
    if (std::find(names.begin(), names.end(), scene) == names.end())
    {
      return "unknown scene '" + scene +
        "' (expected outdoor, paraview, model, street, blocks, glass, glass-opaque, smoke, "
        "smoke-opaque, contour, timesteps or bigmesh)";
    }
  }
  options.bench.Scenes = SplitList(value);
  return options.bench.Scenes.empty() ? "no scene given" : std::string();
}

std::string CheckSetups(const std::vector<std::string>& setups)
{
  for (const std::string& setup : setups)
  {
    if (!shadowscenes::IsLightSetup(setup))
    {
      return "unknown light set-up '" + setup +
        "' (expected overhead, perpendicular, behind, facing, spot, point, wide-spot, "
        "street-point, lamp-behind, soft-sun, soft-sun-D (D degrees across, up to 30), "
        "soft-spot, soft-point, soft-spot-P or soft-point-P (radius P% of the camera's "
        "distance, up to 25))";
    }
  }
  return setups.empty() ? "no light set-up given" : std::string();
}

std::string ParseSetups(const std::string& value, Options& options)
{
  if (value == "all" || value == "soft")
  {
    options.bench.Setups = value == "soft" ? std::vector<std::string>() : shadowscenes::LightSetupNames();
    for (const std::string& sized : shadowscenes::SizedLightSetupNames())
    {
      options.bench.Setups.push_back(sized);
    }
    return {};
  }
  options.bench.Setups = SplitList(value);
  return CheckSetups(options.bench.Setups);
}

std::string ParseFlickerSetups(const std::string& value, Options& options)
{
  options.bench.FlickerSetups = SplitList(value);
  return CheckSetups(options.bench.FlickerSetups);
}

std::string ParseTechniques(const std::string& value, Options& options)
{
  if (value == "all")
  {
    options.bench.Techniques = shadowbench::DefaultTechniqueNames();
    return {};
  }
  for (const std::string& technique : SplitList(value))
  {
    if (!shadowbench::IsTechnique(technique))
    {
      return UnknownTechnique(technique);
    }
  }
  options.bench.Techniques = SplitList(value);
  return options.bench.Techniques.empty() ? "no technique given" : std::string();
}

std::string ParseBenchResolution(const std::string& value, Options& options)
{
  std::string error = ParseResolution(value, options);
  options.bench.Resolution = options.resolution;
  return error;
}

std::string ParseBenchSize(const std::string& value, Options& options)
{
  std::string error = ParseSize(value, options);
  options.bench.Width = options.width;
  options.bench.Height = options.height;
  return error;
}

std::string ParseFlickerFrames(const std::string& value, Options& options)
{
  int frames = 0;
  if (!ParseInt(value, frames) || frames == 1 || frames < 0 || frames > 600)
  {
    return "flicker frames '" + value + "' is not 0 or an integer in 2..600";
  }
  options.bench.FlickerFrames = frames;
  return {};
}

std::string ParseFlickerYaw(const std::string& value, Options& options)
{
  double degrees = 0.0;
  if (!ParseDouble(value, degrees) || !(degrees >= 0.0 && degrees <= 180.0))
  {
    return "flicker yaw '" + value + "' is not a number of degrees in 0..180";
  }
  options.bench.FlickerYawDegrees = degrees;
  return {};
}

std::string ParseTimedFrames(const std::string& value, Options& options)
{
  int frames = 0;
  if (!ParseInt(value, frames) || frames < 1 || frames > 100)
  {
    return "timed frames '" + value + "' is not an integer in 1..100";
  }
  options.bench.TimedFrames = frames;
  return {};
}

std::string ParseMoving(const std::string& value, Options& options)
{
  if (value != "interactive" && value != "still" && value != "movie" && value != "data")
  {
    return "moving '" + value + "' is none of interactive, still, movie and data";
  }
  options.interactiveMoving = value == "interactive";
  options.movingData = value == "data";
  options.movie = value == "movie";
  return {};
}

std::string ParseOutputDirectory(const std::string& value, Options& options)
{
  if (value.empty())
  {
    return "output directory name is empty";
  }
  options.bench.OutputDirectory = value;
  return {};
}

/** Whole-string unsigned 64-bit integer. */
bool ParseUnsigned64(const std::string& text, std::uint64_t& value)
{
  if (text.empty() || !std::isdigit(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  const unsigned long long parsed = std::strtoull(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0')
  {
    return false;
  }
  value = static_cast<std::uint64_t>(parsed);
  return true;
}

std::string ParseCases(const std::string& value, Options& options)
{
  int cases = 0;
  if (!ParseInt(value, cases) || cases < 1 || cases > 1000000)
  {
    return "cases '" + value + "' is not an integer in 1..1000000";
  }
  options.sweep.Cases = cases;
  return {};
}

std::string ParseFirstCase(const std::string& value, Options& options)
{
  int first = 0;
  if (!ParseInt(value, first) || first < 0 || first > 1000000)
  {
    return "first case '" + value + "' is not an integer in 0..1000000";
  }
  options.sweep.FirstCase = first;
  return {};
}

std::string ParseCountedOnly(const std::string& value, Options& options)
{
  if (value != "yes" && value != "no")
  {
    return "counted-only '" + value + "' is neither yes nor no";
  }
  options.sweep.CountedOnly = value == "yes";
  return {};
}

std::string ParseSeed(const std::string& value, Options& options)
{
  return ParseUnsigned64(value, options.sweep.Seed)
    ? std::string()
    : "seed '" + value + "' is not an integer in 0..18446744073709551615";
}

std::string ParseReplay(const std::string& value, Options& options)
{
  options.sweep.Replay = true;
  return ParseUnsigned64(value, options.sweep.ReplaySeed)
    ? std::string()
    : "replay seed '" + value + "' is not an integer in 0..18446744073709551615";
}

std::string ParseSweepLights(const std::string& value, Options& options)
{
  if (value != "hard" && value != "sized")
  {
    return "lights '" + value + "' is neither hard nor sized";
  }
  options.sweep.SizedLights = value == "sized";
  return {};
}

std::string ParseSweepTechniques(const std::string& value, Options& options)
{
  std::string error = ParseTechniques(value, options);
  options.sweep.Techniques = options.bench.Techniques;
  if (value == "all") // every technique that casts shadows
  {
    auto& techniques = options.sweep.Techniques;
    techniques.erase(std::remove(techniques.begin(), techniques.end(), "none"), techniques.end());
  }
  return error;
}

std::string ParseSweepResolution(const std::string& value, Options& options)
{
  std::string error = ParseResolution(value, options);
  options.sweep.Resolution = options.resolution;
  return error;
}

std::string ParseSweepSize(const std::string& value, Options& options)
{
  std::string error = ParseSize(value, options);
  options.sweep.BaseWidth = options.width;
  options.sweep.BaseHeight = options.height;
  return error;
}

std::string ParseMinimumCounted(const std::string& value, Options& options)
{
  int counted = 0;
  if (!ParseInt(value, counted) || counted < 0)
  {
    return "minimum counted pixels '" + value + "' is not a non-negative integer";
  }
  options.sweep.MinimumCounted = counted;
  return {};
}

std::string ParseSweepOutputDirectory(const std::string& value, Options& options)
{
  std::string error = ParseOutputDirectory(value, options);
  options.sweep.OutputDirectory = options.bench.OutputDirectory;
  return error;
}

// --- command line --------------------------------------------------------------

std::string ParseGalleryCases(const std::string& value, Options& options)
{
  options.gallery.Cases.clear();
  for (const std::string& key : SplitList(value))
  {
    shadowgallery::Case c;
    if (!shadowgallery::CaseOfKey(key, c))
    {
      return "gallery case '" + key + "' is not scene:set-up (for instance city:perpendicular)";
    }
    const auto& cases = options.gallery.Cases;
    if (std::any_of(cases.begin(), cases.end(),
          [&](const shadowgallery::Case& known) { return shadowgallery::CaseKey(known) == key; }))
    {
      return "gallery case '" + key + "' given twice";
    }
    options.gallery.Cases.push_back(c);
  }
  return options.gallery.Cases.empty() ? "no gallery case given" : std::string();
}

std::string ParsePage(const std::string& value, Options& options)
{
  if (value.empty())
  {
    return "page name is empty";
  }
  options.gallery.PagePath = value;
  return {};
}

using OptionParser = std::function<std::string(const std::string&, Options&)>;

/** Options taking a value, by every name they are spelled with. */
const std::map<std::string, OptionParser>& RenderOptionParsers()
{
  static const std::map<std::string, OptionParser> parsers = {
    { "--scene", ParseScene },
    { "--up", ParseUp },
    { "--light", ParseLight },
    { "--azimuth", ParseAzimuth },
    { "--elevation", ParseElevation },
    { "--technique", ParseTechnique },
    { "--resolution", ParseResolution },
    { "--filter", ParseFilter },
    { "--size", ParseSize },
    { "-o", ParseOutput },
    { "--output", ParseOutput },
  };
  return parsers;
}

const std::map<std::string, OptionParser>& BenchOptionParsers(bool withScenes)
{
  static const std::map<std::string, OptionParser> common = {
    { "--setups", ParseSetups },
    { "--techniques", ParseTechniques },
    { "--technique", ParseTechniques },
    { "--resolution", ParseBenchResolution },
    { "--size", ParseBenchSize },
    { "--flicker-frames", ParseFlickerFrames },
    { "--flicker-setups", ParseFlickerSetups },
    { "--flicker-yaw", ParseFlickerYaw },
    { "--timed-frames", ParseTimedFrames },
    { "--out", ParseOutputDirectory },
  };
  static const std::map<std::string, OptionParser> bench = [] {
    auto parsers = common;
    parsers["--scenes"] = ParseScenes;
    return parsers;
  }();
  return withScenes ? bench : common;
}

/** Bench's options without the scenes, with the model's up axis. */
const std::map<std::string, OptionParser>& AnalyzeOptionParsers()
{
  static const std::map<std::string, OptionParser> parsers = [] {
    auto analyze = BenchOptionParsers(false);
    analyze["--up"] = ParseUp;
    return analyze;
  }();
  return parsers;
}

/** Bench's options without the flicker path, and the street among the scenes. */
const std::map<std::string, OptionParser>& SpeedOptionParsers()
{
  static const std::map<std::string, OptionParser> parsers = [] {
    auto speed = BenchOptionParsers(false);
    speed.erase("--flicker-frames");
    speed.erase("--flicker-setups");
    speed.erase("--flicker-yaw");
    speed["--scenes"] = ParseSpeedScenes;
    speed["--moving"] = ParseMoving;
    return speed;
  }();
  return parsers;
}

/** The speed benchmark's defaults, in the bench options its parsers fill. */
void SetSpeedDefaults(Options& options)
{
  const shadowbench::SpeedOptions speed;
  options.bench.Scenes = speed.Scenes;
  options.bench.Setups = speed.Setups;
  options.bench.Techniques = speed.Techniques;
  options.bench.Width = speed.Width;
  options.bench.Height = speed.Height;
  options.bench.TimedFrames = speed.TimedFrames;
  options.bench.OutputDirectory = speed.OutputDirectory;
}

shadowbench::SpeedOptions SpeedOptionsOf(const Options& options)
{
  shadowbench::SpeedOptions speed;
  speed.Scenes = options.bench.Scenes;
  speed.Setups = options.bench.Setups;
  speed.Techniques = options.bench.Techniques;
  speed.Resolutions = { options.bench.Resolution, 64 };
  speed.Width = options.bench.Width;
  speed.Height = options.bench.Height;
  speed.TimedFrames = options.bench.TimedFrames;
  speed.InteractiveMoving = options.interactiveMoving;
  speed.MovingData = options.movingData;
  speed.AnimationKeepsViews = options.movie;
  speed.OutputDirectory = options.bench.OutputDirectory;
  return speed;
}

/** Bench's techniques, size, resolution and folder, with the cases and the page. */
const std::map<std::string, OptionParser>& GalleryOptionParsers()
{
  static const std::map<std::string, OptionParser> parsers = {
    { "--cases", ParseGalleryCases },
    { "--page", ParsePage },
    { "--techniques", ParseTechniques },
    { "--resolution", ParseBenchResolution },
    { "--size", ParseBenchSize },
    { "--out", ParseOutputDirectory },
  };
  return parsers;
}

/** The gallery's defaults, in the bench options its parsers fill. */
void SetGalleryDefaults(Options& options)
{
  options.bench.Techniques = options.gallery.Techniques;
  options.bench.Resolution = options.gallery.Resolution;
  options.bench.Width = options.gallery.Width;
  options.bench.Height = options.gallery.Height;
  options.bench.OutputDirectory = options.gallery.OutputDirectory;
}

shadowgallery::Options GalleryOptionsOf(const Options& options)
{
  shadowgallery::Options gallery = options.gallery;
  gallery.Techniques = options.bench.Techniques;
  gallery.Resolution = options.bench.Resolution;
  gallery.Width = options.bench.Width;
  gallery.Height = options.bench.Height;
  gallery.OutputDirectory = options.bench.OutputDirectory;
  return gallery;
}

const std::map<std::string, OptionParser>& SweepOptionParsers()
{
  static const std::map<std::string, OptionParser> parsers = {
    { "--cases", ParseCases },
    { "--seed", ParseSeed },
    { "--first-case", ParseFirstCase },
    { "--counted-only", ParseCountedOnly },
    { "--techniques", ParseSweepTechniques },
    { "--resolution", ParseSweepResolution },
    { "--size", ParseSweepSize },
    { "--min-counted", ParseMinimumCounted },
    { "--replay", ParseReplay },
    { "--lights", ParseSweepLights },
    { "--out", ParseSweepOutputDirectory },
  };
  return parsers;
}

bool IsHelpFlag(const std::string& argument)
{
  return argument == "-h" || argument == "--help";
}

/**
 * Parses the options after the subcommand. Values follow their option
 * ("--resolution 1024") or are attached to it ("--resolution=1024").
 */
bool ParseSubcommandOptions(const std::vector<std::string>& arguments, std::size_t first,
  const std::map<std::string, OptionParser>& parsers, Options& options, std::string& error)
{
  for (std::size_t i = first; i < arguments.size(); ++i)
  {
    std::string name = arguments[i];
    if (IsHelpFlag(name))
    {
      options.help = true;
      return true;
    }
    std::string value;
    bool hasValue = false;
    const std::size_t equals = name.find('=');
    if (name.compare(0, 2, "--") == 0 && equals != std::string::npos)
    {
      value = name.substr(equals + 1);
      name = name.substr(0, equals);
      hasValue = true;
    }
    const auto parser = parsers.find(name);
    if (parser == parsers.end())
    {
      error = "unknown option '" + name + "' for " + options.command;
      return false;
    }
    if (!hasValue)
    {
      // A following option is not a value ("--scene --light sun"); negative
      // numbers ("--azimuth -30") are.
      if (i + 1 >= arguments.size() || arguments[i + 1].compare(0, 2, "--") == 0)
      {
        error = "option " + name + " needs a value";
        return false;
      }
      value = arguments[++i];
    }
    error = parser->second(value, options);
    if (!error.empty())
    {
      return false;
    }
  }
  return true;
}

/** Parses everything after the program name. */
bool ParseCommandLine(
  const std::vector<std::string>& arguments, Options& options, std::string& error)
{
  if (arguments.empty())
  {
    error = "missing subcommand (expected render, gallery, bench, analyze, sweep or speed)";
    return false;
  }
  if (IsHelpFlag(arguments[0]) || arguments[0] == "help")
  {
    options.help = true;
    options.command = arguments[0] == "help" && arguments.size() > 1 ? arguments[1] : "";
    return true;
  }
  options.command = arguments[0];
  if (options.command == "render")
  {
    return ParseSubcommandOptions(arguments, 1, RenderOptionParsers(), options, error);
  }
  if (options.command == "bench")
  {
    return ParseSubcommandOptions(arguments, 1, BenchOptionParsers(true), options, error);
  }
  if (options.command == "sweep")
  {
    return ParseSubcommandOptions(arguments, 1, SweepOptionParsers(), options, error);
  }
  if (options.command == "gallery")
  {
    SetGalleryDefaults(options);
    return ParseSubcommandOptions(arguments, 1, GalleryOptionParsers(), options, error);
  }
  if (options.command == "speed")
  {
    SetSpeedDefaults(options);
    return ParseSubcommandOptions(arguments, 1, SpeedOptionParsers(), options, error);
  }
  if (options.command == "analyze")
  {
    if (arguments.size() < 2 || arguments[1].empty() || arguments[1][0] == '-')
    {
      if (arguments.size() >= 2 && IsHelpFlag(arguments[1]))
      {
        options.help = true;
        return true;
      }
      error = "analyze needs a model FILE";
      return false;
    }
    options.bench = shadowbench::QuickAnalyzeOptions();
    options.bench.ModelFile = arguments[1];
    return ParseSubcommandOptions(arguments, 2, AnalyzeOptionParsers(), options, error);
  }
  error = "unknown subcommand '" + arguments[0] + "' (expected render, gallery, bench, analyze, sweep or speed)";
  return false;
}

// --- rendering -------------------------------------------------------------------

bool BuildScene(vtkRenderer* renderer, const Options& options, std::string& error)
{
  if (options.scene == "default")
  {
    if (options.bench.Up != shadowscenes::UpAxis::Auto)
    {
      error = "--up turns a model file (--scene FILE); the built-in scene is Z-up";
      return false;
    }
    shadowscenes::BuildDefaultScene(renderer);
    return true;
  }
  shadowscenes::ModelUp up;
  if (!shadowscenes::BuildFileScene(renderer, options.scene, options.bench.Up, up, error))
  {
    return false;
  }
  std::cerr << shadowscenes::DescribeModelUp(up) << std::endl;
  return true;
}

void ApplyTechnique(vtkRenderer* renderer, vtkRenderWindow* window, const Options& options)
{
  if (options.technique == "vtk")
  {
    window->SetMultiSamples(0); // as in VTK's test: the pass does not resolve MSAA
    renderer->SetPass(shadowbench::MakeVTKShadowMapPass(static_cast<unsigned int>(options.resolution)));
    return;
  }
  const shadowbench::TechniqueInstance technique =
    shadowbench::MakeTechnique(options.technique, options.light == "point", options.resolution);
  if (auto* depth = vtkDepthShadowMapPass::SafeDownCast(technique.Ours))
  {
    depth->SetFilter(options.filter);
    depth->SetKernelSize(options.kernelSize);
  }
  renderer->SetPass(technique.Pass);
}

bool WritePNG(vtkRenderWindow* window, const std::string& path, std::string& error)
{
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->ReadFrontBufferOff();
  capture->SetInputBufferTypeToRGB();

  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(capture->GetOutputPort());
  const int wasOn = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOff();
  writer->Write();
  vtkObject::SetGlobalWarningDisplay(wasOn);
  if (writer->GetErrorCode() != 0)
  {
    error = "cannot write '" + path + "'";
    return false;
  }
  return true;
}

/** The absolute output path, if its directory exists (checked before rendering). */
bool ResolveOutputPath(const std::string& output, std::string& path, std::string& error)
{
  std::error_code pathError;
  const std::filesystem::path absolute =
    std::filesystem::absolute(output, pathError).lexically_normal();
  if (pathError)
  {
    error = "cannot resolve output path '" + output + "': " + pathError.message();
    return false;
  }
  if (!std::filesystem::is_directory(absolute.parent_path(), pathError))
  {
    error = "cannot write '" + absolute.string() + "': no such directory";
    return false;
  }
  path = absolute.string();
  return true;
}

bool RunRender(const Options& options, std::string& error)
{
  std::string outputPath;
  if (!ResolveOutputPath(options.output, outputPath, error))
  {
    return false;
  }
  vtkNew<vtkRenderer> renderer;
  if (!BuildScene(renderer, options, error))
  {
    return false;
  }
  shadowscenes::AddLight(renderer, options.light, options.azimuth, options.elevation);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(options.width, options.height);
  window->AddRenderer(renderer);
  ApplyTechnique(renderer, window, options);
  window->Render();

  if (!WritePNG(window, outputPath, error))
  {
    return false;
  }
  std::cout << outputPath << std::endl;
  return true;
}

int Fail(const std::string& error)
{
  std::cerr << "vtkshadows: error: " << error << std::endl;
  return ExitUsageError;
}

int Run(const std::vector<std::string>& arguments)
{
  if (arguments.empty())
  {
    PrintUsage(std::cerr);
    return ExitUsageError;
  }

  Options options;
  std::string error;
  if (!ParseCommandLine(arguments, options, error))
  {
    return Fail(error);
  }
  if (options.help)
  {
    PrintUsage(std::cout, options.command);
    return EXIT_SUCCESS;
  }
  bool ok = false;
  if (options.command == "render")
  {
    ok = RunRender(options, error);
  }
  else if (options.command == "sweep")
  {
    ok = shadowsweep::Run(options.sweep, std::cout, std::cerr, error);
  }
  else if (options.command == "speed")
  {
    ok = shadowbench::RunSpeed(SpeedOptionsOf(options), std::cout, std::cerr, error);
  }
  else if (options.command == "gallery")
  {
    ok = shadowgallery::Run(GalleryOptionsOf(options), std::cout, std::cerr, error);
  }
  else
  {
    ok = shadowbench::Run(options.bench, std::cout, std::cerr, error);
  }
  if (!ok)
  {
    return Fail(error);
  }
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char* argv[])
{
  try
  {
    return Run(std::vector<std::string>(argv + 1, argv + argc));
  }
  catch (const std::exception& exception)
  {
    return Fail(exception.what());
  }
}
