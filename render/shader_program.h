#pragma once
#include <string>

#include <Eigen/Core>

namespace hdprior::render {

// A linked vertex + fragment program. Needs a current GL context; throws Error naming the
// program with the compiler's log on failure.
class ShaderProgram {
 public:
  ShaderProgram(const std::string& name, const char* vertexSource, const char* fragmentSource);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const;
  void set(const char* uniform, const Eigen::Matrix4f& value) const;
  void set(const char* uniform, const Eigen::Vector4f& value) const;
  void set(const char* uniform, float value) const;
  void set(const char* uniform, int value) const;

 private:
  unsigned id_ = 0;
};

// The programs every layer draws with, built once per context.
struct ShaderLibrary {
  ShaderLibrary();
  ShaderProgram colored;   // per-vertex colour points and lines
  ShaderProgram textured;  // raster quads
};

}  // namespace hdprior::render
