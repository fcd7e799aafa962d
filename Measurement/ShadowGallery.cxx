#include "ShadowGallery.h"

#include "ShadowBench.h"
#include "ShadowScenes.h"
#include "ShadowTechniques.h"

#include <vtkImageAppend.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace shadowgallery
{
namespace
{
namespace fs = std::filesystem;

/// Cases in the overview picture, from the first.
constexpr int OverviewCases = 3;

std::string CaseName(const Case& c)
{
  return shadowbench::CaseName(c.Scene, c.Setup);
}

/// The link name GitHub gives a heading: lower case, spaces to hyphens, other
/// punctuation but hyphens and underscores dropped.
std::string HeadingAnchor(const std::string& heading)
{
  std::string anchor;
  for (const char c : heading)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '-' || c == '_')
    {
      anchor += static_cast<char>(std::tolower(u));
    }
    else if (c == ' ')
    {
      anchor += '-';
    }
  }
  return anchor;
}

std::string TechniqueTitle(const std::string& technique)
{
  static const std::map<std::string, std::string> titles = {
    { "vtk", "VTK's vtkShadowMapPass" },
    { "auto", "this module's default (automatic)" },
    { "uniform", "focused uniform map" },
    { "lispsm", "LiSPSM" },
    { "csm", "4 cascades" },
    { "dual", "dual depth (no bias)" },
    { "evsm4", "EVSM (moments)" },
  };
  const auto title = titles.find(technique);
  return title != titles.end() ? title->second : technique;
}

/// The PNGs appended along `axis` (0: left to right; 1: bottom to top, VTK's
/// rows counting up), or null if one cannot be read.
vtkSmartPointer<vtkImageData> Appended(const std::vector<std::string>& inputs, int axis)
{
  vtkNew<vtkImageAppend> append;
  append->SetAppendAxis(axis);
  for (const std::string& input : inputs)
  {
    vtkNew<vtkPNGReader> reader;
    if (!reader->CanReadFile(input.c_str()))
    {
      return nullptr;
    }
    reader->SetFileName(input.c_str());
    reader->Update();
    append->AddInputData(reader->GetOutput());
  }
  append->Update();
  return append->GetOutput();
}

bool WriteImage(vtkImageData* image, const std::string& path)
{
  if (!image)
  {
    return false;
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetCompressionLevel(9);
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
  return writer->GetErrorCode() == 0 && fs::exists(path);
}

/// The frame beside its error map, one PNG.
bool WriteFrameAndErrors(
  const std::string& frame, const std::string& errors, const std::string& path)
{
  return WriteImage(Appended({ frame, errors }, 0), path);
}

/// The README's picture: for the first OverviewCases cases, VTK's frame, the
/// default's and the truth side by side, one case a row.
bool WriteOverview(const Options& options, const std::string& scratch, const std::string& folder,
  std::string& error)
{
  const auto& techniques = options.Techniques;
  if (std::find(techniques.begin(), techniques.end(), "vtk") == techniques.end() ||
    std::find(techniques.begin(), techniques.end(), "auto") == techniques.end())
  {
    return true; // nothing to set side by side
  }
  vtkNew<vtkImageAppend> rows;
  rows->SetAppendAxis(1);
  const size_t count = std::min(options.Cases.size(), static_cast<size_t>(OverviewCases));
  for (size_t r = count; r-- > 0;) // bottom row first
  {
    const std::string stem = scratch + "/" + CaseName(options.Cases[r]);
    auto row = Appended({ stem + "-vtk-frame.png", stem + "-auto-frame.png", stem + "-truth.png" }, 0);
    if (!row)
    {
      error = CaseName(options.Cases[r]) + ": cannot compose the overview";
      return false;
    }
    rows->AddInputData(row);
  }
  rows->Update();
  if (!WriteImage(rows->GetOutput(), folder + "/overview.png"))
  {
    error = "cannot write " + folder + "/overview.png";
    return false;
  }
  return true;
}

/// The source's commit, when this program was built from a git checkout.
std::string SourceCommit()
{
#ifdef SHADOWMAPS_SOURCE_DIR
  const std::string command =
    "git -C '" SHADOWMAPS_SOURCE_DIR "' describe --always --dirty=' with local changes' 2>/dev/null";
  std::string commit;
  if (FILE* pipe = popen(command.c_str(), "r"))
  {
    char buffer[128];
    while (fgets(buffer, sizeof(buffer), pipe))
    {
      commit += buffer;
    }
    pclose(pipe);
  }
  commit.erase(std::remove(commit.begin(), commit.end(), '\n'), commit.end());
  if (!commit.empty())
  {
    return commit;
  }
#endif
  return "not recorded";
}

std::string Percent(double value)
{
  return shadowbench::FormatNumber(value, 2) + " %";
}

const shadowbench::CaseFigures* FiguresOf(const std::vector<shadowbench::CaseFigures>& figures,
  const Case& c, const std::string& technique)
{
  const auto found = std::find_if(figures.begin(), figures.end(), [&](const auto& f) {
    return f.Scene == c.Scene && f.Setup == c.Setup && f.Technique == technique;
  });
  return found != figures.end() ? &*found : nullptr;
}

/// The figure a case is judged by: the misclassified pixels, or under
/// translucent casters and volumes the light's mean error (in % of full light),
/// since a shadow there is partial, not lit or shadowed.
double HeadlineFigure(const shadowbench::CaseFigures& f)
{
  return f.Translucent ? 100.0 * f.TransmittanceError : f.Errors.Misclassified;
}

bool IsTranslucentCase(const std::vector<shadowbench::CaseFigures>& figures, const Case& c)
{
  return std::any_of(figures.begin(), figures.end(), [&](const auto& f) {
    return f.Scene == c.Scene && f.Setup == c.Setup && f.Translucent;
  });
}

bool WriteCSV(const Options& options, const std::vector<shadowbench::CaseFigures>& figures,
  const std::string& folder)
{
  std::ofstream csv(folder + "/gallery.csv");
  csv << "scene,light,technique,misclassified,leak,false_shadow,counted_pixels,"
         "light_error,choice\n";
  csv << std::setprecision(12);
  for (const Case& c : options.Cases)
  {
    for (const std::string& technique : options.Techniques)
    {
      if (const auto* f = FiguresOf(figures, c, technique))
      {
        csv << c.Scene << ',' << c.Setup << ',' << technique << ',' << f->Errors.Misclassified
            << ',' << f->Errors.LightLeak << ',' << f->Errors.FalseShadow << ','
            << f->Errors.Counted << ',' << (f->Translucent ? HeadlineFigure(*f) : NAN)
            << ",\"" << f->Choice << "\"\n";
      }
    }
  }
  return static_cast<bool>(csv);
}

std::string Joined(const std::vector<std::string>& items)
{
  std::string joined;
  for (const std::string& item : items)
  {
    joined += (joined.empty() ? "" : ",") + item;
  }
  return joined;
}

/// The command that makes this gallery again, naming the cases and techniques
/// where they are not the defaults.
std::string CommandOf(const Options& options, const std::string& page)
{
  std::ostringstream command;
  command << "vtkshadows gallery --out " << options.OutputDirectory << " --page " << page;
  std::vector<std::string> cases;
  for (const Case& c : options.Cases)
  {
    cases.push_back(CaseKey(c));
  }
  std::vector<std::string> defaultCases;
  for (const Case& c : DefaultCases())
  {
    defaultCases.push_back(CaseKey(c));
  }
  if (cases != defaultCases)
  {
    command << " --cases " << Joined(cases);
  }
  if (options.Techniques != DefaultTechniques())
  {
    command << " --techniques " << Joined(options.Techniques);
  }
  command << " --size " << options.Width << 'x' << options.Height << " --resolution "
          << options.Resolution;
  return command.str();
}

void WriteSummary(const Options& options, const std::vector<shadowbench::CaseFigures>& figures,
  std::ostream& page)
{
  page << "| misclassified % |";
  for (const std::string& technique : options.Techniques)
  {
    page << ' ' << technique << " |";
  }
  page << "\n|---|";
  for (size_t t = 0; t < options.Techniques.size(); ++t)
  {
    page << "---:|";
  }
  page << '\n';
  for (const Case& c : options.Cases)
  {
    page << "| [" << CaseName(c) << "](#" << HeadingAnchor(CaseName(c)) << ")"
         << (IsTranslucentCase(figures, c) ? " (light error %)" : "") << " |";
    for (const std::string& technique : options.Techniques)
    {
      const auto* f = FiguresOf(figures, c, technique);
      page << ' ' << (f ? shadowbench::FormatNumber(HeadlineFigure(*f), 2) : "n/a") << " |";
    }
    page << '\n';
  }
}

void WriteCase(const Options& options, const std::vector<shadowbench::CaseFigures>& figures,
  const Case& c, const std::string& images, std::ostream& page)
{
  const std::string name = CaseName(c);
  page << "\n## " << name << "\n\n" << c.Caption << " (`--scenes " << c.Scene << " --setups "
       << c.Setup << "`).\n\n";
  page << "The ray-cast truth:\n\n![" << name << ", ray-cast truth](" << images << name
       << "-truth.png)\n\n";
  const bool translucent = IsTranslucentCase(figures, c);
  page << (translucent
      ? "| technique | its frame, and where it is wrong | mean error of the light |\n"
        "|---|---|---:|\n"
      : "| technique | its frame, and where it is wrong | misclassified | light leaks | false "
        "shadows |\n|---|---|---:|---:|---:|\n");
  for (const std::string& technique : options.Techniques)
  {
    const auto* f = FiguresOf(figures, c, technique);
    if (!f)
    {
      continue;
    }
    page << "| " << TechniqueTitle(technique) << " (`" << technique << "`)";
    if (!f->Choice.empty())
    {
      page << ": " << f->Choice;
    }
    page << " | ![" << name << ", " << technique << "](" << images << name << '-' << technique
         << ".png) | ";
    if (translucent)
    {
      page << Percent(HeadlineFigure(*f)) << " |\n";
      continue;
    }
    page << Percent(f->Errors.Misclassified) << " | " << Percent(f->Errors.LightLeak) << " | "
         << Percent(f->Errors.FalseShadow) << " |\n";
  }
}

bool WritePage(const Options& options, const std::vector<shadowbench::CaseFigures>& figures,
  const std::string& commit, const std::string& pagePath)
{
  const fs::path pageFolder = fs::absolute(pagePath).parent_path();
  std::string images =
    fs::absolute(options.OutputDirectory).lexically_relative(pageFolder).generic_string();
  images = images.empty() || images == "." ? "" : images + "/";
  std::ofstream page(pagePath);
  page << "# Gallery\n\n"
       << "Each scene below is seen once and drawn by VTK's `vtkShadowMapPass`, by this "
          "module's default and by each technique, beside the ray-cast truth. Each frame "
          "stands beside its error map: red where light leaks into a true shadow, blue where "
          "a shadow is drawn on a lit surface, grey where the frame agrees with the truth "
          "(dark grey in shadow), black where nothing is counted (the background, surfaces "
          "facing away from the light or seen through glass). Misclassified is the share of the surface pixels the light "
          "faces whose lit or shadowed state differs from the truth's (a sized light's at half "
          "its visibility). Under translucent casters and volumes a shadow is partial and "
          "tinted: there the figure is the mean error of the light reaching the surface, "
          "|frame's − truth's| per colour channel, in % of full light, and the error map is "
          "red where the frame is lighter than the truth and blue where it is darker, in "
          "proportion (full at half the light); a sized light's map is drawn the same way "
          "against its visibility (against the transmittance where casters are "
          "translucent).\n\n"
       << "The materials are white and purely diffuse so that a frame's ratio to the frame "
          "without shadows is its shadow factor; the pictures add "
       << static_cast<int>(100.0f * shadowmetrics::ShownAmbient + 0.5f)
       << " % of the unshadowed frame as an ambient term, so that shapes stay visible in "
          "shadow.\n\n"
       << "Made by `" << CommandOf(options, pagePath) << "` at source " << commit
       << "; maps of " << options.Resolution
       << "² texels (cascades: 4 of half that), VTK's pass at its default 1024².\n\n";
  if (fs::exists(options.OutputDirectory + "/overview.png"))
  {
    page << "![VTK's pass, this module's default and the ray-cast truth, side by side, in the "
            "first cases below](" << images << "overview.png)\n\n"
         << "Left to right: VTK's `vtkShadowMapPass`, this module's default "
            "(`vtkAutomaticShadowMapPass`), the ray-cast truth; top to bottom: the first "
         << std::min(options.Cases.size(), static_cast<size_t>(OverviewCases))
         << " cases below.\n\n";
  }
  WriteSummary(options, figures, page);
  for (const Case& c : options.Cases)
  {
    WriteCase(options, figures, c, images, page);
  }
  return static_cast<bool>(page);
}

/// Composes the benchmark's frames into `folder`: the truth, then each
/// technique's frame beside its error map.
bool ComposeImages(
  const Options& options, const std::string& scratch, const std::string& folder, std::string& error)
{
  for (const Case& c : options.Cases)
  {
    const std::string name = CaseName(c);
    std::error_code failed;
    fs::copy_file(scratch + "/" + name + "-truth.png", folder + "/" + name + "-truth.png",
      fs::copy_options::overwrite_existing, failed);
    if (failed)
    {
      error = name + ": no truth picture (" + failed.message() + ")";
      return false;
    }
    for (const std::string& technique : options.Techniques)
    {
      const std::string stem = scratch + "/" + name + "-" + technique;
      if (!WriteFrameAndErrors(stem + "-frame.png", stem + "-errors.png",
            folder + "/" + name + "-" + technique + ".png"))
      {
        error = name + ", " + technique + ": cannot compose its picture";
        return false;
      }
    }
  }
  return true;
}

/// Copies every file of `composed` into the gallery's folder, and removes an
/// overview this run did not make, so that no picture of an earlier run is
/// left beside this one's figures.
bool Publish(const std::string& composed, const std::string& folder, std::string& error)
{
  std::error_code failed;
  if (!fs::exists(composed + "/overview.png"))
  {
    fs::remove(folder + "/overview.png", failed);
  }
  fs::directory_iterator files(composed, failed);
  if (failed)
  {
    error = "cannot read " + composed + ": " + failed.message();
    return false;
  }
  for (const auto& entry : files)
  {
    fs::copy_file(entry.path(), folder / entry.path().filename(),
      fs::copy_options::overwrite_existing, failed);
    if (failed)
    {
      error = "cannot write " + (fs::path(folder) / entry.path().filename()).string() + ": " +
        failed.message();
      return false;
    }
  }
  return true;
}

/// A new folder of its own under the system's temporary folder.
bool MakeScratchFolder(std::string& scratch, std::string& error)
{
  std::error_code failed;
  fs::path base = fs::temp_directory_path(failed);
  if (failed)
  {
    base = "/tmp";
  }
  std::string pattern = (base / "vtkshadows-gallery-XXXXXX").string();
  if (!mkdtemp(pattern.data()))
  {
    error = "cannot make a scratch folder in " + base.string();
    return false;
  }
  scratch = pattern;
  return true;
}

/// The page's folder must exist before minutes of measuring.
bool CheckPageFolder(const std::string& page, std::string& error)
{
  std::error_code failed;
  const fs::path folder = fs::absolute(page, failed).parent_path();
  if (failed || !fs::is_directory(folder, failed))
  {
    error = "cannot write the page '" + page + "': no such directory";
    return false;
  }
  return true;
}

shadowbench::Options BenchOptionsOf(const Options& options, const std::string& scratch)
{
  shadowbench::Options bench;
  for (const Case& c : options.Cases)
  {
    bench.Cases.emplace_back(c.Scene, c.Setup);
  }
  bench.Techniques = options.Techniques;
  bench.Resolution = options.Resolution;
  bench.Width = options.Width;
  bench.Height = options.Height;
  bench.FlickerFrames = 0;
  bench.TimedFrames = 1;
  bench.OutputDirectory = scratch;
  bench.WriteFrames = true;
  return bench;
}
} // namespace

//------------------------------------------------------------------------------
std::vector<Case> DefaultCases()
{
  return {
    { "street", "perpendicular",
      "A street of box buildings and poles, 225 actors, seen from the pavement, the sun 35° "
      "up and from the side" },
    { "outdoor", "perpendicular",
      "Ten thousand poles and balls out to the horizon, the same sun: the scene that costs "
      "VTK's pass nearly every shadow" },
    { "model", "spot", "A model under a spot light" },
    { "outdoor", "street-point", "A lamp among the poles, low over the ground" },
    { "glass", "perpendicular",
      "Coloured glass panes over the ground: shadows tinted by what the light crosses" },
    { "smoke", "perpendicular", "A smoke volume beside a ball and poles: a partial shadow" },
    { "paraview", "soft-spot-3",
      "A ParaView-style isosurface, slice and tubes under a spot light with a size (a radius "
      "3 % of the camera's distance): soft shadows" },
  };
}

//------------------------------------------------------------------------------
std::vector<std::string> DefaultTechniques()
{
  return { "vtk", "auto", "uniform", "lispsm", "csm", "dual", "evsm4" };
}

//------------------------------------------------------------------------------
std::string CaseKey(const Case& c)
{
  return c.Scene + ":" + c.Setup;
}

//------------------------------------------------------------------------------
bool CaseOfKey(const std::string& key, Case& c)
{
  for (const Case& known : DefaultCases())
  {
    if (CaseKey(known) == key)
    {
      c = known;
      return true;
    }
  }
  const auto colon = key.find(':');
  const std::vector<std::string> scenes = shadowscenes::SceneNames();
  if (colon == std::string::npos || !shadowscenes::IsLightSetup(key.substr(colon + 1)) ||
    std::find(scenes.begin(), scenes.end(), key.substr(0, colon)) == scenes.end())
  {
    return false;
  }
  c = { key.substr(0, colon), key.substr(colon + 1), key.substr(0, colon) + " under " +
      key.substr(colon + 1) };
  return true;
}

//------------------------------------------------------------------------------
bool Run(const Options& options, std::ostream& out, std::ostream& log, std::string& error)
{
  if (options.Cases.empty() || options.Techniques.empty())
  {
    error = "no case or no technique to show";
    return false;
  }
  const std::string page =
    options.PagePath.empty() ? options.OutputDirectory + "/gallery.md" : options.PagePath;
  std::string scratch;
  if (!shadowbench::MakeOutputDirectory(options.OutputDirectory, error) ||
    !CheckPageFolder(page, error) || !MakeScratchFolder(scratch, error))
  {
    return false;
  }
  // Before anything is written: the page and the pictures are in the tree.
  const std::string commit = SourceCommit();
  const std::string composed = scratch + "/gallery";
  std::vector<shadowbench::CaseFigures> figures;
  std::ostringstream table;
  std::error_code failed;
  bool made = fs::create_directory(composed, failed);
  if (!made)
  {
    error = "cannot make " + composed + ": " + failed.message();
  }
  made = made &&
    shadowbench::Run(BenchOptionsOf(options, scratch), table, log, error, &figures) &&
    ComposeImages(options, scratch, composed, error) &&
    WriteOverview(options, scratch, composed, error);
  if (made && !WriteCSV(options, figures, composed))
  {
    error = "cannot write " + composed + "/gallery.csv";
    made = false;
  }
  made = made && Publish(composed, options.OutputDirectory, error);
  std::error_code ignored;
  fs::remove_all(scratch, ignored);
  if (!made)
  {
    return false;
  }
  if (!WritePage(options, figures, commit, page))
  {
    error = "cannot write the page '" + page + "'";
    return false;
  }
  out << fs::absolute(page).string() << std::endl;
  return true;
}

} // namespace shadowgallery
