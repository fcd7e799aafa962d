// Which way is up in a user's model: the scenes here are Z-up, models come
// Y-up (glTF by its specification, most OBJ and PLY files by their modellers'
// habit), Z-up (STL from CAD) or any other way. Pure: no VTK.
#ifndef ShadowModelUp_h
#define ShadowModelUp_h

#include <array>
#include <string>

namespace shadowscenes
{

/// A model's up axis, or Auto: ChooseModelUp decides.
enum class UpAxis
{
  Auto,
  PlusX,
  MinusX,
  PlusY,
  MinusY,
  PlusZ,
  MinusZ
};

/// "x", "y", "z", "-x", "-y", "-z" (a leading "+" allowed, any case); false for
/// anything else.
bool ParseUpAxis(const std::string& text, UpAxis& axis);

/// "+x" ... "-z", "auto".
std::string UpAxisName(UpAxis axis);

/// The axis chosen and why, in words for a printed line.
struct ModelUp
{
  UpAxis Axis = UpAxis::PlusZ;
  std::string Reason;
};

/**
 * The up axis of a model of file extension `extension` (lower case, with its
 * dot) and bounds (xmin, xmax, ymin, ymax, zmin, zmax), where `requested` is
 * Auto; else `requested` itself. Auto takes, in order:
 *  - glTF (.gltf, .glb): +y, its specification's;
 *  - a model that stands on a coordinate plane: +axis for the axis whose
 *    minimum is 0 (within 1% of the model's extent along it) while the other
 *    two cross 0: modellers put their ground at 0 along their up axis and
 *    centre the model over the origin;
 *  - else the format's habit: +y for OBJ and PLY, +z for STL and VTP.
 */
ModelUp ChooseModelUp(UpAxis requested, const std::string& extension, const std::array<double, 6>& bounds);

/// One line: the axis chosen, why, and how to choose another.
std::string DescribeModelUp(const ModelUp& chosen);

/// The rotation, row-major, that turns `axis` into +z (a proper rotation about
/// x or y; the identity for +z and Auto).
std::array<double, 9> RotationToZUp(UpAxis axis);

} // namespace shadowscenes

#endif
