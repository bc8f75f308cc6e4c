#pragma once
// GLSL 330 programs: <name>.vert and <name>.frag, built into the program (shaders/, embedded at
// build time by cmake/embed_shaders.cmake) or read at run time from a directory.
// A missing file or a compile/link failure throws Error with the path and the compiler's log.
#include <string>

namespace cablefilm {

// The shader directory: `option` when not empty, else $CABLEFILM_SHADERS when set, else ""
// (the shaders built into the program).
std::string ResolveShaderDir(const std::string& option);

// The built-in shader `file` ("shape.vert", ...) into `text`; false when there is none.
bool FindEmbeddedShader(const std::string& file, std::string* text);

class ShaderProgram {
 public:
  // `dir` empty: the built-in shaders. Needs a current context.
  ShaderProgram(const std::string& dir, const std::string& name);
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
