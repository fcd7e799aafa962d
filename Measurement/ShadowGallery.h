// The gallery behind `vtkshadows gallery`: a few scenes, each seen once, drawn
// by VTK's vtkShadowMapPass, this module's default and each technique beside
// the ray-cast truth, every picture with its error map and its misclassified
// pixels. The benchmark (ShadowBench.h) measures; this composes its frames
// into the pictures and the page docs/GALLERY.md.
#ifndef ShadowGallery_h
#define ShadowGallery_h

#include <iosfwd>
#include <string>
#include <vector>

namespace shadowgallery
{

/// A scene (shadowscenes::BuildSceneByName) under a light set-up
/// (shadowscenes::LightSetupNames), with a caption saying what it shows.
struct Case
{
  std::string Scene;
  std::string Setup;
  std::string Caption;
};

/// A street and a field of poles under a side sun, a model under a spot, a lamp among boxes, a
/// glass and a smoke caster, and a sized lamp.
std::vector<Case> DefaultCases();

/// VTK's pass, the automatic pass (the default), the focused uniform map,
/// LiSPSM, cascades, dual depth and EVSM.
std::vector<std::string> DefaultTechniques();

/// "scene:setup" of `c`, as --cases takes it.
std::string CaseKey(const Case& c);

/// The case of DefaultCases with that key, or one of that scene
/// (shadowscenes::SceneNames) and set-up captioned by the two; false if either
/// name is unknown.
bool CaseOfKey(const std::string& key, Case& c);

struct Options
{
  std::vector<Case> Cases = DefaultCases();
  std::vector<std::string> Techniques = DefaultTechniques();
  /// Each picture's size; the composed image is twice as wide (the frame,
  /// then its error map).
  int Width = 400;
  int Height = 225;
  int Resolution = 2048;
  std::string OutputDirectory = "gallery";
  /// The markdown page; empty: gallery.md in OutputDirectory. Its image
  /// links are relative to its own folder.
  std::string PagePath;
};

/// Measures the cases (ShadowBench with frames written, in a scratch folder
/// removed afterwards; the page's folder must exist) and, once every picture
/// is made, writes into OutputDirectory, per case,
/// <scene>-<setup>-truth.png and <scene>-<setup>-<technique>.png (the frame
/// beside its error map: light leaks red, false shadows blue), gallery.csv
/// (every figure), the page and, when the techniques include vtk and auto,
/// overview.png: VTK's frame, the default's and the truth side by side for
/// the first three cases. Prints the page's path on `out`; progress
/// goes to `log`. False with a one-line `error` on bad options or failure.
bool Run(const Options& options, std::ostream& out, std::ostream& log, std::string& error);

} // namespace shadowgallery

#endif
