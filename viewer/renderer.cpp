#include "viewer/renderer.h"

#include <glad/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace radmesh {

namespace {

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 radiosity;
uniform mat4 viewProjection;
uniform vec3 eye;
out vec3 vertexRadiosity;
out float facing;  // > 0 on the lit (front) side; linear across a flat triangle, so exact
void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
  vertexRadiosity = radiosity;
  facing = dot(normal, eye - position);
  // A wall of no thickness is two polygons back to back: the back of one lies at the depth of the
  // other's front but for rounding, and must lose to it. Backs are drawn a little deeper: 2e-5 of
  // the depth range, some 300 steps of a 24-bit buffer.
  if (facing <= 0.0) gl_Position.z += 2e-5 * gl_Position.w;
}
)";

const char* kFragmentShader = R"(#version 330 core
in vec3 vertexRadiosity;
in float facing;
uniform float exposure;
uniform vec3 tint;
uniform float tintAmount;
out vec4 colour;
// IEC 61966-2-1 within 0.4 of an 8-bit level: its power 1/2.4 fitted by square roots, which
// llvmpipe computes far faster than pow (the encoding was a third of a frame's time).
vec3 srgbFromLinear(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  vec3 s1 = sqrt(c), s2 = sqrt(s1), s3 = sqrt(s2);
  return mix(12.92 * c, 0.585122381 * s1 + 0.783140355 * s2 - 0.368262736 * s3, step(0.0031308, c));
}
void main() {
  // Polygons are one-sided: their back shows a dark blue-grey so that it is not taken for light.
  vec3 linear = facing > 0.0 ? vertexRadiosity * exposure : vec3(0.010, 0.012, 0.020);
  colour = vec4(srgbFromLinear(mix(linear, tint, tintAmount)), 1.0);
}
)";

unsigned compileShader(GLenum type, const char* source) {
  const unsigned shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("renderer shader does not compile: ") + log);
  }
  return shader;
}

unsigned linkProgram() {
  const unsigned vertex = compileShader(GL_VERTEX_SHADER, kVertexShader);
  const unsigned fragment = compileShader(GL_FRAGMENT_SHADER, kFragmentShader);
  const unsigned program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    glDeleteProgram(program);
    throw std::runtime_error(std::string("renderer program does not link: ") + log);
  }
  return program;
}

std::vector<float> toFloats(const std::vector<Vec3>& values) {
  std::vector<float> floats;
  floats.reserve(values.size() * 3);
  for (const Vec3& v : values) floats.insert(floats.end(), {float(v.x), float(v.y), float(v.z)});
  return floats;
}

void fillAttribute(unsigned buffer, unsigned location, const std::vector<float>& data, GLenum usage) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), usage);
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
}

}  // namespace

Renderer::Renderer() : program_(linkProgram()) {
  viewProjectionLocation_ = glGetUniformLocation(program_, "viewProjection");
  eyeLocation_ = glGetUniformLocation(program_, "eye");
  exposureLocation_ = glGetUniformLocation(program_, "exposure");
  tintLocation_ = glGetUniformLocation(program_, "tint");
  tintAmountLocation_ = glGetUniformLocation(program_, "tintAmount");
  glGenVertexArrays(1, &vertexArray_);
  unsigned buffers[5];
  glGenBuffers(5, buffers);
  positionBuffer_ = buffers[0];
  normalBuffer_ = buffers[1];
  radiosityBuffer_ = buffers[2];
  indexBuffer_ = buffers[3];
  highlightIndexBuffer_ = buffers[4];
}

Renderer::~Renderer() {
  const unsigned buffers[5] = {positionBuffer_, normalBuffer_, radiosityBuffer_, indexBuffer_,
                               highlightIndexBuffer_};
  glDeleteBuffers(5, buffers);
  glDeleteVertexArrays(1, &vertexArray_);
  glDeleteProgram(program_);
}

void Renderer::setMesh(const DisplayMesh& mesh) {
  if (mesh.normals.size() != mesh.positions.size() || mesh.indices.size() % 3 != 0 ||
      mesh.patchOfTriangle.size() != mesh.indices.size() / 3)
    throw std::invalid_argument("display mesh is inconsistent: positions, normals, indices and "
                                "patchOfTriangle sizes disagree");
  for (unsigned i : mesh.indices)
    if (i >= mesh.positions.size())
      throw std::invalid_argument("display mesh index " + std::to_string(i) + " is past its " +
                                  std::to_string(mesh.positions.size()) + " vertices");
  for (int p : mesh.patchOfTriangle)
    if (p < 0) throw std::invalid_argument("display mesh has a triangle with a negative patch index");
  vertexCount_ = mesh.positions.size();
  indexCount_ = mesh.indices.size();
  indices_ = mesh.indices;
  const BoundingBox box = boundingBox(mesh.positions);
  origin_ = mesh.positions.empty() ? Vec3(0.0) : 0.5 * (box.low + box.high);
  std::vector<Vec3> local(mesh.positions);
  for (Vec3& p : local) p -= origin_;
  glBindVertexArray(vertexArray_);
  fillAttribute(positionBuffer_, 0, toFloats(local), GL_STATIC_DRAW);
  fillAttribute(normalBuffer_, 1, toFloats(mesh.normals), GL_STATIC_DRAW);
  fillAttribute(radiosityBuffer_, 2, std::vector<float>(vertexCount_ * 3, 0.0f), GL_DYNAMIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indexCount_ * sizeof(unsigned)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);

  // Triangles grouped by patch (a counting sort), so a highlight costs only its own triangles.
  int patchCount = 0;
  for (int p : mesh.patchOfTriangle) patchCount = std::max(patchCount, p + 1);
  firstTriangleOfPatch_.assign(static_cast<size_t>(patchCount) + 1, 0);
  for (int p : mesh.patchOfTriangle) ++firstTriangleOfPatch_[static_cast<size_t>(p) + 1];
  for (size_t p = 1; p < firstTriangleOfPatch_.size(); ++p)
    firstTriangleOfPatch_[p] += firstTriangleOfPatch_[p - 1];
  trianglesByPatch_.assign(mesh.patchOfTriangle.size(), 0);
  std::vector<size_t> next(firstTriangleOfPatch_.begin(), firstTriangleOfPatch_.end() - 1);
  for (size_t t = 0; t < mesh.patchOfTriangle.size(); ++t)
    trianglesByPatch_[next[static_cast<size_t>(mesh.patchOfTriangle[t])]++] = static_cast<unsigned>(t);
  highlightIndexCount_ = 0;
  firstIndexOfCell_.clear();
  visibleCells_.clear();
}

void Renderer::setCells(const std::vector<int>& cellOfPatch, int cells) {
  const size_t patches = firstTriangleOfPatch_.empty() ? 0 : firstTriangleOfPatch_.size() - 1;
  if (cellOfPatch.size() < patches)
    throw std::invalid_argument("cells given for " + std::to_string(cellOfPatch.size()) + " patches, not the mesh's " +
                                std::to_string(patches));
  auto group = [&](size_t p) { return cellOfPatch[p] < 0 || cellOfPatch[p] >= cells ? cells : cellOfPatch[p]; };
  firstIndexOfCell_.assign(static_cast<size_t>(cells) + 2, 0);
  for (size_t p = 0; p < patches; ++p)
    firstIndexOfCell_[group(p) + 1] += 3 * (firstTriangleOfPatch_[p + 1] - firstTriangleOfPatch_[p]);
  for (size_t c = 1; c < firstIndexOfCell_.size(); ++c) firstIndexOfCell_[c] += firstIndexOfCell_[c - 1];
  std::vector<unsigned> byCell(indexCount_);
  std::vector<size_t> next(firstIndexOfCell_.begin(), firstIndexOfCell_.end() - 1);
  for (size_t p = 0; p < patches; ++p)
    for (size_t i = firstTriangleOfPatch_[p]; i < firstTriangleOfPatch_[p + 1]; ++i) {
      const size_t t = trianglesByPatch_[i];
      std::copy(indices_.begin() + 3 * t, indices_.begin() + 3 * t + 3, byCell.begin() + next[group(p)]);
      next[group(p)] += 3;
    }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(byCell.size() * sizeof(unsigned)), byCell.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

void Renderer::setVisibleCells(std::vector<bool> visible) { visibleCells_ = std::move(visible); }

void Renderer::setVertexRadiosity(const std::vector<Rgb>& vertexB) {
  if (vertexB.size() != vertexCount_)
    throw std::invalid_argument("vertex radiosity has " + std::to_string(vertexB.size()) +
                                " values for a mesh of " + std::to_string(vertexCount_) + " vertices");
  // Uploaded as a fraction of the largest value, the scale going with the exposure (in double):
  // floats hold radiosity up to 3e38 only, and past that a bright scene drew black (inf x 0).
  double largest = 0.0;
  for (const Rgb& b : vertexB)
    for (int c = 0; c < 3; ++c)
      if (std::isfinite(b[c])) largest = std::max(largest, std::abs(b[c]));
  radiosityScale_ = largest > 0.0 ? largest : 1.0;
  std::vector<Rgb> scaled(vertexB.size());
  for (size_t v = 0; v < vertexB.size(); ++v) scaled[v] = vertexB[v] / radiosityScale_;
  const std::vector<float> floats = toFloats(scaled);
  glBindBuffer(GL_ARRAY_BUFFER, radiosityBuffer_);
  glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(floats.size() * sizeof(float)), floats.data());
}

void Renderer::setHighlightedPatches(const std::vector<int>& patches) {
  std::vector<unsigned> highlight;
  for (int p : patches) {
    if (p < 0 || static_cast<size_t>(p) + 1 >= firstTriangleOfPatch_.size()) continue;
    for (size_t i = firstTriangleOfPatch_[p]; i < firstTriangleOfPatch_[p + 1]; ++i) {
      const size_t t = trianglesByPatch_[i];
      highlight.insert(highlight.end(), indices_.begin() + 3 * t, indices_.begin() + 3 * t + 3);
    }
  }
  highlightIndexCount_ = highlight.size();
  glBindVertexArray(vertexArray_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, highlightIndexBuffer_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(highlight.size() * sizeof(unsigned)),
               highlight.data(), GL_DYNAMIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
  glBindVertexArray(0);
}

void Renderer::drawVisibleCells() const {
  const size_t cells = firstIndexOfCell_.empty() ? 0 : firstIndexOfCell_.size() - 2;
  if (visibleCells_.size() != cells || cells == 0) {
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indexCount_), GL_UNSIGNED_INT, nullptr);
    return;
  }
  // Runs of cells drawn, one call each; the outside (the last group) always.
  for (size_t c = 0; c <= cells;) {
    if (c < cells && !visibleCells_[c]) {
      ++c;
      continue;
    }
    const size_t first = firstIndexOfCell_[c];
    while (c < cells && visibleCells_[c]) ++c;
    if (c == cells) ++c;  // the outside follows the last cell
    const size_t count = firstIndexOfCell_[c] - first;
    if (count > 0)
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(first * sizeof(unsigned)));
  }
}

void Renderer::draw(const RenderView& view, glm::ivec2 framebufferSize, const Shading& shading) {
  glViewport(0, 0, framebufferSize.x, framebufferSize.y);
  glClearColor(kBackgroundRgb[0], kBackgroundRgb[1], kBackgroundRgb[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (indexCount_ == 0 || framebufferSize.x <= 0 || framebufferSize.y <= 0) return;

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);  // the highlight pass redraws the same triangles at the same depth
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glUseProgram(program_);
  RenderView local = view;  // in the frame the positions were uploaded in
  local.eye -= origin_;
  local.look -= origin_;
  const glm::mat4 viewProjection =
      viewProjectionMatrix(local, double(framebufferSize.x) / double(framebufferSize.y));
  glUniformMatrix4fv(viewProjectionLocation_, 1, GL_FALSE, glm::value_ptr(viewProjection));
  glUniform3f(eyeLocation_, float(local.eye.x), float(local.eye.y), float(local.eye.z));
  glUniform1f(exposureLocation_, float(shading.exposure * radiosityScale_));
  glUniform3f(tintLocation_, 1.0f, 0.25f, 0.9f);
  glUniform1f(tintAmountLocation_, 0.0f);
  glBindVertexArray(vertexArray_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
  drawVisibleCells();

  if (shading.highlightShooters && highlightIndexCount_ > 0) {
    // Shooters: a translucent magenta fill and a solid outline, pulled towards the eye.
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, highlightIndexBuffer_);
    glUniform1f(tintAmountLocation_, 0.45f);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(highlightIndexCount_), GL_UNSIGNED_INT, nullptr);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonOffset(-1.0f, -1.0f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glUniform1f(tintAmountLocation_, 1.0f);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(highlightIndexCount_), GL_UNSIGNED_INT, nullptr);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_POLYGON_OFFSET_LINE);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
  }
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace radmesh
