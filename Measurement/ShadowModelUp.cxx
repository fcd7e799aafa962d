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

UpAxis Plus(int axis)
{
  static const UpAxis axes[3] = { UpAxis::PlusX, UpAxis::PlusY, UpAxis::PlusZ };
  return axes[axis];
}

bool Straddles(double low, double high)
{
  return low < 0.0 && high > 0.0;
}

// The axes along which the model stands on the plane coordinate = 0 (its
// minimum there, its maximum above) while the other two cross 0: a model
// placed on its modeller's ground and centred over the origin.
std::vector<UpAxis> AxesStoodOn(const std::array<double, 6>& bounds)
{
  std::vector<UpAxis> stood;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double low = bounds[2 * axis];
    const double high = bounds[2 * axis + 1];
    const double extent = high - low;
    const int others[2] = { (axis + 1) % 3, (axis + 2) % 3 };
    if (extent > 0.0 && std::isfinite(extent) && std::abs(low) <= RestTolerance * extent &&
      Straddles(bounds[2 * others[0]], bounds[2 * others[0] + 1]) &&
      Straddles(bounds[2 * others[1]], bounds[2 * others[1] + 1]))
    {
      stood.push_back(Plus(axis));
    }
  }
  return stood;
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
  const std::vector<UpAxis> stood = AxesStoodOn(bounds);
  if (stood.size() == 1)
  {
    return { stood[0],
      "the model stands on the plane " + UpAxisName(stood[0]).substr(1) + " = 0" };
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
