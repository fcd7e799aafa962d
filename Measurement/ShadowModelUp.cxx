#include "ShadowModelUp.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

namespace shadowscenes
{
namespace
{
constexpr double RestTolerance = 0.01; // of the model's extent along the axis

UpAxis Signed(int axis, bool plus)
{
  static const UpAxis plusAxes[3] = { UpAxis::PlusX, UpAxis::PlusY, UpAxis::PlusZ };
  static const UpAxis minusAxes[3] = { UpAxis::MinusX, UpAxis::MinusY, UpAxis::MinusZ };
  return plus ? plusAxes[axis] : minusAxes[axis];
}

// The axes along which the model stands on the plane coordinate = 0, signed
// the way it stands: +axis when it lies above the plane, -axis below.
std::vector<UpAxis> AxesResting(const std::array<double, 6>& bounds)
{
  std::vector<UpAxis> resting;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double low = bounds[2 * axis];
    const double high = bounds[2 * axis + 1];
    const double extent = high - low;
    if (!(extent > 0.0) || !std::isfinite(extent))
    {
      continue;
    }
    const bool lowAtZero = std::abs(low) <= RestTolerance * extent;
    const bool highAtZero = std::abs(high) <= RestTolerance * extent;
    if (lowAtZero != highAtZero)
    {
      resting.push_back(Signed(axis, lowAtZero));
    }
  }
  return resting;
}
} // namespace

bool ParseUpAxis(const std::string& text, UpAxis& axis)
{
  std::string name;
  for (const char c : text)
  {
    name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  if (name.size() == 2 && name[0] == '+')
  {
    name = name.substr(1);
  }
  static const std::pair<const char*, UpAxis> names[] = { { "x", UpAxis::PlusX },
    { "-x", UpAxis::MinusX }, { "y", UpAxis::PlusY }, { "-y", UpAxis::MinusY },
    { "z", UpAxis::PlusZ }, { "-z", UpAxis::MinusZ } };
  for (const auto& entry : names)
  {
    if (name == entry.first)
    {
      axis = entry.second;
      return true;
    }
  }
  return false;
}

std::string UpAxisName(UpAxis axis)
{
  switch (axis)
  {
    case UpAxis::PlusX:
      return "+x";
    case UpAxis::MinusX:
      return "-x";
    case UpAxis::PlusY:
      return "+y";
    case UpAxis::MinusY:
      return "-y";
    case UpAxis::PlusZ:
      return "+z";
    case UpAxis::MinusZ:
      return "-z";
    case UpAxis::Auto:
      break;
  }
  return "auto";
}

ModelUp ChooseModelUp(
  UpAxis requested, const std::string& extension, const std::array<double, 6>& bounds)
{
  if (requested != UpAxis::Auto)
  {
    return { requested, "as asked" };
  }
  if (extension == ".gltf" || extension == ".glb")
  {
    return { UpAxis::PlusY, "glTF is Y-up by its specification" };
  }
  const std::vector<UpAxis> resting = AxesResting(bounds);
  if (resting.size() == 1)
  {
    const std::string name = UpAxisName(resting[0]);
    return { resting[0],
      "the model stands on the plane " + name.substr(1) + " = 0, on its " + name + " side" };
  }
  if (extension == ".obj" || extension == ".ply")
  {
    return { UpAxis::PlusY, "OBJ and PLY models are most often Y-up" };
  }
  return { UpAxis::PlusZ,
    extension == ".stl" ? "STL models are most often Z-up (CAD's habit)"
                        : "VTK data keep their axes, and the scene is Z-up" };
}

std::string DescribeModelUp(const ModelUp& chosen)
{
  return "model up axis: " + UpAxisName(chosen.Axis) + " (" + chosen.Reason +
    "); --up x|y|z|-x|-y|-z to choose another";
}

std::array<double, 9> RotationToZUp(UpAxis axis)
{
  switch (axis)
  {
    case UpAxis::PlusX: // -90 degrees about y: x -> z, z -> -x
      return { 0, 0, -1, 0, 1, 0, 1, 0, 0 };
    case UpAxis::MinusX: // +90 degrees about y: -x -> z
      return { 0, 0, 1, 0, 1, 0, -1, 0, 0 };
    case UpAxis::PlusY: // +90 degrees about x: y -> z, z -> -y
      return { 1, 0, 0, 0, 0, -1, 0, 1, 0 };
    case UpAxis::MinusY: // -90 degrees about x: -y -> z
      return { 1, 0, 0, 0, 0, 1, 0, -1, 0 };
    case UpAxis::MinusZ: // 180 degrees about x
      return { 1, 0, 0, 0, -1, 0, 0, 0, -1 };
    case UpAxis::PlusZ:
    case UpAxis::Auto:
      break;
  }
  return { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
}

} // namespace shadowscenes
