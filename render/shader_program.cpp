#include "render/shader_program.h"

#include <string>

#include "engine/error.h"
#include "render/embedded_shaders.h"
#include "render/gl.h"

namespace hdprior::render {
namespace {

GLuint compile(const std::string& name, GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw Error("shader " + name, std::string("compile failed: ") + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& name, const char* vertexSource, const char* fragmentSource) {
  const GLuint vs = compile(name + ".vert", GL_VERTEX_SHADER, vertexSource);
  const GLuint fs = compile(name + ".frag", GL_FRAGMENT_SHADER, fragmentSource);
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetProgramInfoLog(id_, sizeof log, nullptr, log);
    glDeleteProgram(id_);
    throw Error("shader " + name, std::string("link failed: ") + log);
  }
}

ShaderProgram::~ShaderProgram() { glDeleteProgram(id_); }

void ShaderProgram::use() const { glUseProgram(id_); }
void ShaderProgram::set(const char* uniform, const Eigen::Matrix4f& value) const {
  glUniformMatrix4fv(glGetUniformLocation(id_, uniform), 1, GL_FALSE, value.data());  // Eigen is column-major
}
void ShaderProgram::set(const char* uniform, const Eigen::Vector4f& value) const {
  glUniform4fv(glGetUniformLocation(id_, uniform), 1, value.data());
}
void ShaderProgram::set(const char* uniform, float value) const {
  glUniform1f(glGetUniformLocation(id_, uniform), value);
}
void ShaderProgram::set(const char* uniform, int value) const {
  glUniform1i(glGetUniformLocation(id_, uniform), value);
}

ShaderLibrary::ShaderLibrary()
    : colored("colored", shaders::colored_vert, shaders::colored_frag),
      textured("textured", shaders::textured_vert, shaders::textured_frag) {}

}  // namespace hdprior::render
