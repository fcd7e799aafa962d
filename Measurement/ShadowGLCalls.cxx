#include "ShadowGLCalls.h"

#include "ShadowMapVTKCompat.h" // the GL loader

namespace shadowbench
{
namespace
{
GLCallCounts Counts;

// The GL's calling convention is the platform's default where this runs
// (Linux), as the loaders declare it there.
template <typename Result, typename... Arguments>
using FunctionPointer = Result (*)(Arguments...);

// One counted function: `Slot` is the loader's pointer (the name its macro
// expands to), `Counter` the count it adds to.
template <typename Function, Function* Slot, long GLCallCounts::*Counter>
struct Counted;

template <typename Result, typename... Arguments, FunctionPointer<Result, Arguments...>* Slot,
  long GLCallCounts::*Counter>
struct Counted<FunctionPointer<Result, Arguments...>, Slot, Counter>
{
  static inline FunctionPointer<Result, Arguments...> Original = nullptr;

  static Result Call(Arguments... arguments)
  {
    ++(Counts.*Counter);
    return Original(arguments...);
  }

  static void Install()
  {
    if (*Slot != nullptr && *Slot != &Call)
    {
      Original = *Slot;
      *Slot = &Call;
    }
  }

  static void Uninstall()
  {
    if (*Slot == &Call)
    {
      *Slot = Original;
    }
  }

  static void Swap(bool install) { install ? Install() : Uninstall(); }
};

// The loader's pointer behind a GL function's name, and the wrapper for it.
#define SHADOW_COUNT(name, counter)                                                              \
  Counted<decltype(name), &(name), &GLCallCounts::counter>::Swap(Install)

template <bool Install>
void SwapCounters()
{
  SHADOW_COUNT(glDrawRangeElements, Draws);
  SHADOW_COUNT(glDrawArraysInstanced, Draws);
  SHADOW_COUNT(glDrawElementsInstanced, Draws);
  SHADOW_COUNT(glUniform1f, UniformSets);
  SHADOW_COUNT(glUniform1fv, UniformSets);
  SHADOW_COUNT(glUniform1i, UniformSets);
  SHADOW_COUNT(glUniform1iv, UniformSets);
  SHADOW_COUNT(glUniform2fv, UniformSets);
  SHADOW_COUNT(glUniform2iv, UniformSets);
  SHADOW_COUNT(glUniform3fv, UniformSets);
  SHADOW_COUNT(glUniform4fv, UniformSets);
  SHADOW_COUNT(glUniformMatrix3fv, UniformSets);
  SHADOW_COUNT(glUniformMatrix4fv, UniformSets);
  SHADOW_COUNT(glUseProgram, ProgramBinds);
  SHADOW_COUNT(glBindVertexArray, VertexArrayBinds);
  SHADOW_COUNT(glBindBuffer, BufferBinds);
}
#undef SHADOW_COUNT
} // namespace

//------------------------------------------------------------------------------
void StartCountingGLCalls()
{
  SwapCounters<true>();
  Counts = GLCallCounts();
}

//------------------------------------------------------------------------------
GLCallCounts StopCountingGLCalls()
{
  SwapCounters<false>();
  return Counts;
}

//------------------------------------------------------------------------------
std::string GLRendererName()
{
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "?") + ", OpenGL " + (version ? version : "?");
}
} // namespace shadowbench
