#include "view/shader_program.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "view/gl_api.h"

namespace cablefilm {

void CheckGl(const std::string& where) {
  std::string codes;
  for (int i = 0; i < 16; ++i) {
    const GLenum e = glGetError();
    if (e == GL_NO_ERROR) break;
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04X", e);
    codes += (codes.empty() ? "" : ", ") + std::string(buf);
  }
  if (!codes.empty()) throw Error("OpenGL error " + codes + " in " + where);
}

std::string ResolveShaderDir(const std::string& option) {
  if (!option.empty()) return option;
  if (const char* env = std::getenv("CABLEFILM_SHADERS"); env && *env) return env;
  return "";
}

namespace {

// The source of `file` in `dir` (empty: built in); `path` names it in messages.
std::string ReadShader(const std::string& dir, const std::string& file, std::string* path) {
  if (dir.empty()) {
    *path = "built-in shaders/" + file;
    std::string text;
    if (!FindEmbeddedShader(file, &text)) throw Error("no " + *path + " in this build");
    return text;
  }
  *path = dir + "/" + file;
  std::ifstream in(*path, std::ios::binary);
  if (!in)
    throw Error("shader " + *path + " not found (set --shaders or CABLEFILM_SHADERS to the "
                "directory holding the .vert/.frag files)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

GLuint Compile(GLenum type, const std::string& dir, const std::string& file) {
  std::string path;
  const std::string source = ReadShader(dir, file, &path);
  const GLuint shader = glCreateShader(type);
  const char* src = source.c_str();
  glShaderSource(shader, 1, &src, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetShaderInfoLog(shader, len, nullptr, log.data());
    glDeleteShader(shader);
    throw Error("shader " + path + " does not compile:\n" + std::string(log.data()));
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& dir, const std::string& name) : name_(name) {
  const std::string base = (dir.empty() ? "built-in shaders" : dir) + "/" + name;
  const GLuint vs = Compile(GL_VERTEX_SHADER, dir, name + ".vert");
  GLuint fs = 0;
  try {
    fs = Compile(GL_FRAGMENT_SHADER, dir, name + ".frag");
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetProgramInfoLog(program_, len, nullptr, log.data());
    glDeleteProgram(program_);
    program_ = 0;
    throw Error("shader program " + base + ".{vert,frag} does not link:\n" + std::string(log.data()));
  }
  CheckGl("building shader program " + base);
}

ShaderProgram::~ShaderProgram() {
  if (program_) glDeleteProgram(program_);
}

void ShaderProgram::Use() const { glUseProgram(program_); }

int ShaderProgram::Uniform(const char* uniform) const {
  const GLint loc = glGetUniformLocation(program_, uniform);
  if (loc < 0) throw Error("shader program '" + name_ + "' has no uniform '" + uniform + "'");
  return loc;
}

}  // namespace cablefilm
