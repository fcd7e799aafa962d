// Whether drawing the casters once for all cascades (layered rendering) would
// cost less than one draw per cascade, measured outside VTK's mappers on the
// surface that changes every frame in the time-varying scene: the wavelet's
// contour at 160 over 221^3 points (about 780k triangles), positions only,
// drawn depth-only into four 2048^2 layers of a depth texture array, as four
// orthographic crops of one light view (each triangle falls in one or two).
//   - one draw per layer, each with its crop (what the cascades do now);
//   - one draw, a geometry shader sending each triangle to the layers its
//     light-space box meets (gl_Layer), in a loop or in instanced invocations;
//   - one draw into one layer (the uniform map), for scale;
// one layer drawn through a program shaped like the mappers' (six outputs the
// casters' branch does not read, as in the programs casters and receivers
// share), and with the casters' slope-scaled polygon offset; and what a
// pass-through geometry shader adds to the scene's own draw (960 x 540, colour
// and depth), where the casters' program would carry it.
// Median of 5 of each, after a warm-up, glFinish around each. One run:
//   build/bin/layered_casters_timing
#if __has_include("vtk_glad.h") // VTK 9.4 replaced GLEW with glad
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif

#include <vtkCellArray.h>
#include <vtkContourFilter.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRTAnalyticSource.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTriangleFilter.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace
{
constexpr int Layers = 4;
constexpr int MapSize = 2048;

struct Mesh
{
  std::vector<float> Positions;
  std::vector<unsigned int> Indices;
  glm::vec3 Min{ 1e30f };
  glm::vec3 Max{ -1e30f };
};

Mesh ContourOfWavelet()
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-110, 110, -110, 110, -110, 110);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(wavelet->GetOutputPort());
  contour->SetValue(0, 160.0);
  contour->ComputeNormalsOff();
  contour->ComputeScalarsOff();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(contour->GetOutputPort());
  triangles->Update();
  vtkPolyData* surface = triangles->GetOutput();
  Mesh mesh;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    for (int a = 0; a < 3; ++a)
    {
      mesh.Positions.push_back(static_cast<float>(p[a]));
      mesh.Min[a] = std::min(mesh.Min[a], static_cast<float>(p[a]));
      mesh.Max[a] = std::max(mesh.Max[a], static_cast<float>(p[a]));
    }
  }
  vtkCellArray* polys = surface->GetPolys();
  vtkNew<vtkIdList> cell;
  for (polys->InitTraversal(); polys->GetNextCell(cell);)
  {
    for (vtkIdType k = 0; k < cell->GetNumberOfIds(); ++k)
    {
      mesh.Indices.push_back(static_cast<unsigned int>(cell->GetId(k)));
    }
  }
  return mesh;
}

// Prints the GL's log for `object` where its status query says it failed.
template <typename GetStatus, typename GetLog>
void ReportFailure(GLuint object, GLenum status, GetStatus getStatus, GetLog getLog, const char* what)
{
  GLint ok = 0;
  getStatus(object, status, &ok);
  if (!ok)
  {
    char log[4096];
    getLog(object, static_cast<GLsizei>(sizeof(log)), nullptr, log);
    std::fprintf(stderr, "%s: %s\n", what, log);
  }
}

GLuint Compile(GLenum stage, const std::string& source)
{
  GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  ReportFailure(
    shader, GL_COMPILE_STATUS,
    [](GLuint s, GLenum q, GLint* v) { glGetShaderiv(s, q, v); },
    [](GLuint s, GLsizei n, GLsizei* l, GLchar* t) { glGetShaderInfoLog(s, n, l, t); }, "shader");
  return shader;
}

GLuint Program(const std::string& vs, const std::string& gs, const std::string& fs)
{
  GLuint program = glCreateProgram();
  glAttachShader(program, Compile(GL_VERTEX_SHADER, vs));
  if (!gs.empty())
  {
    glAttachShader(program, Compile(GL_GEOMETRY_SHADER, gs));
  }
  glAttachShader(program, Compile(GL_FRAGMENT_SHADER, fs));
  glLinkProgram(program);
  ReportFailure(
    program, GL_LINK_STATUS,
    [](GLuint p, GLenum q, GLint* v) { glGetProgramiv(p, q, v); },
    [](GLuint p, GLsizei n, GLsizei* l, GLchar* t) { glGetProgramInfoLog(p, n, l, t); }, "program");
  return program;
}

const char* const Header = "#version 410 core\n";

// One crop per layer: strips of the light view's x range, each overlapping
// the next by a twentieth of the range.
std::vector<glm::mat4> Crops(const Mesh& mesh, glm::mat4& lightView)
{
  const glm::vec3 centre = 0.5f * (mesh.Min + mesh.Max);
  const float radius = glm::length(mesh.Max - mesh.Min) * 0.5f;
  const glm::vec3 direction = glm::normalize(glm::vec3(0.4f, -0.3f, -1.0f));
  lightView = glm::lookAt(centre - 2.0f * radius * direction, centre, glm::vec3(0, 1, 0));
  std::vector<glm::mat4> crops;
  const float width = 2.0f * radius / Layers;
  for (int k = 0; k < Layers; ++k)
  {
    const float left = -radius + k * width - 0.05f * radius;
    const float right = left + width + 0.1f * radius;
    crops.push_back(glm::ortho(left, right, -radius, radius, radius, 3.0f * radius));
  }
  return crops;
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

double TimeMs(const std::function<void()>& draw)
{
  draw(); // warm-up: compiles the program's variant
  glFinish();
  std::vector<double> times;
  for (int i = 0; i < 5; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    draw();
    glFinish();
    times.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return Median(times);
}
} // namespace

int main()
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(960, 540);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  window->MakeCurrent();

  const Mesh mesh = ContourOfWavelet();
  const GLsizei indexCount = static_cast<GLsizei>(mesh.Indices.size());
  std::printf("contour: %zu triangles; %s\n", mesh.Indices.size() / 3,
    reinterpret_cast<const char*>(glGetString(GL_RENDERER)));

  GLuint vao = 0;
  GLuint buffers[2] = { 0, 0 };
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, mesh.Positions.size() * sizeof(float), mesh.Positions.data(),
    GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, mesh.Indices.size() * sizeof(unsigned int),
    mesh.Indices.data(), GL_STATIC_DRAW);

  GLuint depths = 0;
  glGenTextures(1, &depths);
  glBindTexture(GL_TEXTURE_2D_ARRAY, depths);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, MapSize, MapSize, Layers, 0,
    GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  GLuint framebuffer = 0;
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glViewport(0, 0, MapSize, MapSize);

  glm::mat4 lightView;
  const std::vector<glm::mat4> crops = Crops(mesh, lightView);
  std::vector<glm::mat4> matrices;
  for (const glm::mat4& crop : crops)
  {
    matrices.push_back(crop * lightView);
  }

  const std::string emptyFS = std::string(Header) + "void main() {}\n";
  const GLuint perLayer = Program(std::string(Header) +
      "layout(location = 0) in vec3 position;\nuniform mat4 lightMatrix;\n"
      "void main() { gl_Position = lightMatrix * vec4(position, 1.0); }\n",
    "", emptyFS);
  const std::string toLight = std::string(Header) +
    "layout(location = 0) in vec3 position;\nuniform mat4 lightView;\n"
    "void main() { gl_Position = lightView * vec4(position, 1.0); }\n";
  const std::string routeBody =
    "uniform mat4 crops[4];\n"
    "bool Meets(int k) {\n"
    "  vec4 a = crops[k] * gl_in[0].gl_Position;\n"
    "  vec4 b = crops[k] * gl_in[1].gl_Position;\n"
    "  vec4 c = crops[k] * gl_in[2].gl_Position;\n"
    "  vec2 lo = min(a.xy, min(b.xy, c.xy)); vec2 hi = max(a.xy, max(b.xy, c.xy));\n"
    "  return all(lessThanEqual(lo, vec2(1.0))) && all(greaterThanEqual(hi, vec2(-1.0)));\n"
    "}\n"
    "void Emit(int k) {\n"
    "  for (int v = 0; v < 3; ++v) {\n"
    "    gl_Position = crops[k] * gl_in[v].gl_Position; gl_Layer = k; EmitVertex();\n"
    "  }\n"
    "  EndPrimitive();\n"
    "}\n";
  const GLuint routedLoop = Program(toLight,
    std::string(Header) + "layout(triangles) in;\nlayout(triangle_strip, max_vertices = 12) out;\n" +
      routeBody + "void main() { for (int k = 0; k < 4; ++k) if (Meets(k)) Emit(k); }\n",
    emptyFS);
  const GLuint routedInvocations = Program(toLight,
    std::string(Header) +
      "layout(triangles, invocations = 4) in;\nlayout(triangle_strip, max_vertices = 3) out;\n" +
      routeBody + "void main() { if (Meets(gl_InvocationID)) Emit(gl_InvocationID); }\n",
    emptyFS);

  const auto drawLayer = [&](int layer) {
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depths, 0, layer);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUniformMatrix4fv(glGetUniformLocation(perLayer, "lightMatrix"), 1, GL_FALSE,
      glm::value_ptr(matrices[layer]));
    glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
  };
  const auto routed = [&](GLuint program) {
    glUseProgram(program);
    glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depths, 0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUniformMatrix4fv(glGetUniformLocation(program, "lightView"), 1, GL_FALSE,
      glm::value_ptr(lightView));
    glUniformMatrix4fv(glGetUniformLocation(program, "crops"), Layers, GL_FALSE,
      glm::value_ptr(crops[0]));
    glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
  };
  const double oneLayer = TimeMs([&] {
    glUseProgram(perLayer);
    drawLayer(0);
  });
  const double everyLayer = TimeMs([&] {
    glUseProgram(perLayer);
    for (int k = 0; k < Layers; ++k)
    {
      drawLayer(k);
    }
  });
  // One layer through a program of the mappers' shape: the scene's varyings
  // written by the vertex shader, read by the fragment shader in the branch
  // the casters skip (vtkShadowCasting).
  const GLuint sceneShaped = Program(std::string(Header) +
      "layout(location = 0) in vec3 position;\nuniform mat4 lightMatrix;\nuniform mat4 view;\n"
      "out vec4 vertexVC; out vec3 normalVC; out vec4 colorVC; out vec2 tcoord;\n"
      "out vec4 extraA; out vec4 extraB;\n"
      "void main() { vec4 p = vec4(position, 1.0); gl_Position = lightMatrix * p;\n"
      "  vertexVC = view * p; normalVC = mat3(view) * normalize(position);\n"
      "  colorVC = vec4(fract(position), 1.0); tcoord = position.xy;\n"
      "  extraA = view * vertexVC; extraB = lightMatrix * vertexVC; }\n",
    "",
    std::string(Header) +
      "in vec4 vertexVC; in vec3 normalVC; in vec4 colorVC; in vec2 tcoord;\n"
      "in vec4 extraA; in vec4 extraB;\nuniform int casting;\nout vec4 colour;\n"
      "void main() { if (casting != 0) { return; }\n"
      "  colour = colorVC * max(dot(normalize(normalVC), vec3(0, 0, 1)), 0.0) + vertexVC * 1e-3\n"
      "    + vec4(tcoord, 0.0, 0.0) * 1e-3 + extraA * 1e-3 + extraB * 1e-3; }\n");
  const double shaped = TimeMs([&] {
    glUseProgram(sceneShaped);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depths, 0, 0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUniformMatrix4fv(glGetUniformLocation(sceneShaped, "lightMatrix"), 1, GL_FALSE,
      glm::value_ptr(matrices[0]));
    glUniformMatrix4fv(
      glGetUniformLocation(sceneShaped, "view"), 1, GL_FALSE, glm::value_ptr(lightView));
    glUniform1i(glGetUniformLocation(sceneShaped, "casting"), 1);
    glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
  });
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.1f, 4.0f);
  const double offset = TimeMs([&] {
    glUseProgram(perLayer);
    drawLayer(0);
  });
  glDisable(GL_POLYGON_OFFSET_FILL);
  const double loop = TimeMs([&] { routed(routedLoop); });
  const double invocations = TimeMs([&] { routed(routedInvocations); });

  // The scene's draw: colour and depth at the window's size, with and
  // without a geometry shader that passes each triangle on.
  GLuint scene[2] = { 0, 0 };
  glGenTextures(2, scene);
  glBindTexture(GL_TEXTURE_2D, scene[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 960, 540, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindTexture(GL_TEXTURE_2D, scene[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 960, 540, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
    nullptr);
  GLuint sceneBuffer = 0;
  glGenFramebuffers(1, &sceneBuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, sceneBuffer);
  glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, scene[0], 0);
  glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, scene[1], 0);
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glViewport(0, 0, 960, 540);
  const std::string sceneVS = std::string(Header) +
    "layout(location = 0) in vec3 position;\nuniform mat4 camera;\nout vec3 placeVS;\n"
    "void main() { placeVS = position; gl_Position = camera * vec4(position, 1.0); }\n";
  const std::string sceneFS = std::string(Header) +
    "in vec3 place;\nout vec4 colour;\n"
    "void main() { vec3 n = normalize(cross(dFdx(place), dFdy(place)));\n"
    "  colour = vec4(vec3(0.2 + 0.8 * max(n.z, 0.0)), 1.0); }\n";
  std::string plainVS = sceneVS;
  plainVS.replace(plainVS.find("out vec3 placeVS"), 16, "out vec3 place");
  plainVS.replace(plainVS.find("placeVS = position"), 18, "place = position");
  const GLuint plain = Program(plainVS, "", sceneFS);
  const GLuint passedOn = Program(sceneVS,
    std::string(Header) +
      "layout(triangles) in;\nlayout(triangle_strip, max_vertices = 3) out;\n"
      "in vec3 placeVS[];\nout vec3 place;\n"
      "void main() { for (int v = 0; v < 3; ++v) {\n"
      "  place = placeVS[v]; gl_Position = gl_in[v].gl_Position; EmitVertex(); }\n"
      "  EndPrimitive(); }\n",
    sceneFS);
  const glm::vec3 centre = 0.5f * (mesh.Min + mesh.Max);
  const float radius = glm::length(mesh.Max - mesh.Min) * 0.5f;
  const glm::mat4 camera =
    glm::perspective(glm::radians(30.0f), 960.0f / 540.0f, 0.5f * radius, 5.0f * radius) *
    glm::lookAt(centre + glm::vec3(0.0f, -2.5f * radius, 1.5f * radius), centre,
      glm::vec3(0, 0, 1));
  const auto drawScene = [&](GLuint program) {
    glUseProgram(program);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUniformMatrix4fv(
      glGetUniformLocation(program, "camera"), 1, GL_FALSE, glm::value_ptr(camera));
    glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
  };
  const double scenePlain = TimeMs([&] { drawScene(plain); });
  const double sceneWithGS = TimeMs([&] { drawScene(passedOn); });

  std::printf("\n| draw | ms | over one layer |\n|---|---:|---:|\n");
  std::printf("| one layer (a uniform map) | %.1f | 1.00 |\n", oneLayer);
  std::printf("| one layer, through a program of the scene's shape | %.1f | %.2f |\n", shaped,
    shaped / oneLayer);
  std::printf("| one layer, slope-scaled polygon offset on | %.1f | %.2f |\n", offset,
    offset / oneLayer);
  std::printf("| four layers, a draw each (cascades now) | %.1f | %.2f |\n", everyLayer,
    everyLayer / oneLayer);
  std::printf("| four layers, one draw, geometry shader loop | %.1f | %.2f |\n", loop,
    loop / oneLayer);
  std::printf("| four layers, one draw, instanced geometry shader | %.1f | %.2f |\n", invocations,
    invocations / oneLayer);
  std::printf("\n| the scene's draw, 960 x 540 | ms | over without |\n|---|---:|---:|\n");
  std::printf("| without a geometry shader | %.1f | 1.00 |\n", scenePlain);
  std::printf("| with a pass-through geometry shader | %.1f | %.2f |\n", sceneWithGS,
    sceneWithGS / scenePlain);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return 0;
}
