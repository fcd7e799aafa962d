// Counts of the GL calls that make a draw's CPU cost, per frame: draws, uniform
// sets, program, vertex array and buffer binds. The loaders VTK uses (GLEW up
// to 9.3, glad from 9.4) call these through function pointers that every
// library of the process shares; counting swaps in wrappers that count and
// call the original. Only functions that are pointers in both loaders are
// counted (GLEW calls GL 1.1's, glDrawArrays among them, directly): the draws
// counted are the mappers' (glDrawRangeElements and the instanced draws), not
// glDrawArrays' full-screen quads.
#ifndef ShadowGLCalls_h
#define ShadowGLCalls_h

#include <string>

namespace shadowbench
{
struct GLCallCounts
{
  long Draws = 0;
  long UniformSets = 0;
  long ProgramBinds = 0;
  long VertexArrayBinds = 0;
  long BufferBinds = 0;

  long All() const
  {
    return this->Draws + this->UniformSets + this->ProgramBinds + this->VertexArrayBinds +
      this->BufferBinds;
  }
};

/// Starts counting from zero. Call with the window's context current, after
/// its first render (the loader has its pointers then); calling again puts
/// the counters back where a loader reloaded its pointers.
void StartCountingGLCalls();

/// Puts the loader's own pointers back (the wrappers cost a little per call:
/// frames timed after counting must not run through them); returns the counts
/// since StartCountingGLCalls.
GLCallCounts StopCountingGLCalls();

/// The current context's GL_RENDERER and GL_VERSION strings (which GPU, or
/// which software rasteriser, the figures come from).
std::string GLRendererName();
} // namespace shadowbench

#endif
