#pragma once
// GLSL 330 programs loaded from files at run time: <dir>/<name>.vert and <dir>/<name>.frag.
// A missing file or a compile/link failure throws Error with the path and the compiler's log.
#include <string>

namespace cablefilm {

// The shader directory: `option` when not empty, else $CABLEFILM_SHADERS when set, else the
// directory compiled in (CABLEFILM_SHADER_DIR, <source>/shaders).
std::string ResolveShaderDir(const std::string& option);

class ShaderProgram {
 public:
  ShaderProgram(const std::string& dir, const std::string& name);  // needs a current context
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  unsigned id() const { return program_; }
  void Use() const;
  int Uniform(const char* name) const;  // throws Error when the program has no such uniform

 private:
  std::string name_;
  unsigned program_ = 0;
};

}  // namespace cablefilm
