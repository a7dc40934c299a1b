#include "gl/Shader.h"

#include "core/DataPaths.h"
#include "gl/EmbeddedShaders.h"

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace lenslab::gl {
namespace fs = std::filesystem;

namespace {

// Where the text of a shader file comes from: a folder, or the compiled-in copies (nullopt).
class ShaderFiles {
 public:
  explicit ShaderFiles(std::optional<fs::path> folder) : folder_(std::move(folder)) {}

  bool exists(const fs::path& relative) const {
    if (folder_) return fs::exists(*folder_ / relative);
    return embedded(relative) != nullptr;
  }

  std::string read(const fs::path& relative) const {
    if (!folder_) {
      if (const EmbeddedShader* shader = embedded(relative)) return std::string(shader->text);
      throw std::runtime_error("shader " + relative.generic_string() +
                               ": not among the shaders compiled into lenslab (the list in CMakeLists.txt)");
    }
    const fs::path path = *folder_ / relative;
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw std::runtime_error("shader " + path.string() +
                               ": cannot read it (set LENSLAB_SHADER_DIR to lenslab's shaders/ folder)");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

 private:
  static const EmbeddedShader* embedded(const fs::path& relative) {
    const std::string name = relative.generic_string();
    for (const EmbeddedShader& shader : embeddedShaders())
      if (shader.path == name) return &shader;
    return nullptr;
  }

  std::optional<fs::path> folder_;
};

// `file` is relative to the shader folder and normalised ("common/brdf.glsl"), which is also
// the name compile errors give.
void expand(const fs::path& file, const ShaderFiles& files, ShaderSource& out, int depth) {
  if (depth > 16) throw std::runtime_error("shader " + file.generic_string() + ": #include nested too deeply");
  const int fileIndex = static_cast<int>(out.files.size());
  out.files.push_back(file.generic_string());
  if (depth > 0) out.text += "#line 1 " + std::to_string(fileIndex) + "\n";
  std::istringstream in(files.read(file));
  static const std::regex includeLine(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    std::smatch m;
    if (std::regex_match(line, m, includeLine)) {
      fs::path target = (file.parent_path() / m[1].str()).lexically_normal();
      if (!files.exists(target)) target = fs::path(m[1].str()).lexically_normal();
      expand(target, files, out, depth + 1);
      out.text += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(fileIndex) + "\n";
    } else {
      out.text += line + "\n";
    }
  }
}

}  // namespace

ShaderSource loadShaderSource(const fs::path& relativePath, const std::vector<std::string>& defines) {
  return loadShaderSource(relativePath, defines, shaderDirectory());
}

ShaderSource loadShaderSource(const fs::path& relativePath, const std::vector<std::string>& defines,
                              const std::optional<fs::path>& folder) {
  ShaderSource raw;
  expand(relativePath.lexically_normal(), ShaderFiles(folder), raw, 0);
  // Put the defines right after #version (which must stay the first line).
  const std::size_t versionEnd = raw.text.find('\n');
  std::string header = raw.text.substr(0, versionEnd + 1);
  for (const std::string& d : defines) header += "#define " + d + "\n";
  header += "#line 2 0\n";
  raw.text = header + raw.text.substr(versionEnd + 1);
  return raw;
}

std::string annotateInfoLog(const std::string& log, const std::vector<std::string>& files) {
  // Mesa writes "0:12(3): error: ..."; others write "0(12) : error ...".
  static const std::regex location(R"((\d+)[:(](\d+)(\(\d+\))?\)?)");
  std::istringstream in(log);
  std::string line, out;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, location) && m.position(0) == 0) {
      const std::size_t index = std::stoul(m[1].str());
      const std::string name = index < files.size() ? files[index] : "source " + m[1].str();
      line = name + ":" + m[2].str() + m.suffix().str();
    }
    out += (out.empty() ? "" : " | ") + line;
  }
  return out;
}

namespace {

// The driver's log for a shader or a program (getLength/getLog: glGetShaderiv/InfoLog or the
// program pair), without the trailing NUL.
template <class GetIv, class GetLog>
std::string infoLog(GLuint object, GetIv getIv, GetLog getLog) {
  GLint length = 0;
  getIv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  getLog(object, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

Shader compile(GLenum stage, const fs::path& path, const std::vector<std::string>& defines) {
  const ShaderSource source = loadShaderSource(path, defines);
  Shader shader(glCreateShader(stage));
  const char* text = source.text.c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (!ok)
    throw std::runtime_error("shader " + path.generic_string() + " failed to compile: " +
                             annotateInfoLog(infoLog(shader.id(), glGetShaderiv, glGetShaderInfoLog), source.files));
  return shader;
}

}  // namespace

namespace {

Program link(const std::vector<const Shader*>& shaders, const std::string& name) {
  Program program = Program::create();
  for (const Shader* s : shaders) glAttachShader(program.id(), s->id());
  glLinkProgram(program.id());
  for (const Shader* s : shaders) glDetachShader(program.id(), s->id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok)
    throw std::runtime_error("shader program " + name + " failed to link: " +
                             annotateInfoLog(infoLog(program.id(), glGetProgramiv, glGetProgramInfoLog), {}));
  return program;
}

}  // namespace

Program buildProgram(const fs::path& vertexPath, const fs::path& fragmentPath,
                     const std::vector<std::string>& defines) {
  const Shader vs = compile(GL_VERTEX_SHADER, vertexPath, defines);
  const Shader fsh = compile(GL_FRAGMENT_SHADER, fragmentPath, defines);
  return link({&vs, &fsh}, vertexPath.generic_string() + " + " + fragmentPath.generic_string());
}

Program buildProgramWithGeometry(const fs::path& vertexPath, const fs::path& geometryPath, const fs::path& fragmentPath,
                                 const std::vector<std::string>& defines) {
  const Shader vs = compile(GL_VERTEX_SHADER, vertexPath, defines);
  const Shader gs = compile(GL_GEOMETRY_SHADER, geometryPath, defines);
  const Shader fsh = compile(GL_FRAGMENT_SHADER, fragmentPath, defines);
  return link({&vs, &gs, &fsh}, vertexPath.generic_string() + " + " + geometryPath.generic_string() + " + " +
                                    fragmentPath.generic_string());
}

}  // namespace lenslab::gl
