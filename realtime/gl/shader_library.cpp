#include "realtime/gl/shader_library.h"

#include "realtime/gl/extensions.h"

#include "realtime/gl/fault_injection.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <regex>

namespace gib::rt::gl {

std::string_view glslFile(std::string_view path) {
  if (const EmbeddedFile* file = findEmbeddedFile(embeddedShaderFiles(), path)) return file->text;
  throw ShaderError(fmt::format(
      "no embedded shader file '{}' (a path from the project root, of a *.glsl file under "
      "realtime/ or a *_shared.h header under realtime/, common/ or scene/)",
      path));
}

namespace {

constexpr int kMaxIncludeDepth = 16;

std::string_view trimmed(std::string_view row) {
  const std::size_t first = row.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const std::size_t last = row.find_last_not_of(" \t\r");
  return row.substr(first, last - first + 1);
}

bool isConditional(std::string_view directive) {
  return directive.starts_with("#if");  // #if, #ifdef, #ifndef
}

// The C++ side of a shared header: `#ifdef __cplusplus` up to its `#else` or `#endif`, with the
// conditionals nested inside it. GLSL sees what follows `#else`.
class CppOnlyBlocks {
 public:
  // Whether `directive` (a trimmed line) is dropped from the GLSL text.
  bool drops(std::string_view directive) {
    if (depth_ == 0) {
      if (directive == "#ifdef __cplusplus") {
        depth_ = 1;
        in_cpp_ = true;
        return true;
      }
      return false;
    }
    if (isConditional(directive)) {
      ++depth_;
    } else if (directive.starts_with("#endif")) {
      if (--depth_ == 0) {  // the block's own #endif
        in_cpp_ = false;
        return true;
      }
    } else if (depth_ == 1 && directive.starts_with("#else")) {
      in_cpp_ = false;
      return true;
    }
    return in_cpp_;
  }
  bool open() const { return depth_ > 0; }

 private:
  int depth_ = 0;  // conditionals open since `#ifdef __cplusplus`, itself included
  bool in_cpp_ = false;
};

void expandInto(std::string_view path, const GlslLookup& lookup, ExpandedSource& out,
                std::vector<std::string>& stack) {
  if (stack.size() > kMaxIncludeDepth || std::find(stack.begin(), stack.end(), path) != stack.end())
    throw ShaderError(
        fmt::format("{}: #include cycle or nesting deeper than {}", path, kMaxIncludeDepth));
  auto found = std::find(out.files.begin(), out.files.end(), path);
  if (found != out.files.end() && !stack.empty()) return;  // included once, like #pragma once
  const int number = int(out.files.size());
  out.files.emplace_back(path);
  stack.emplace_back(path);
  const std::string_view text = lookup(path);
  int line = 0;
  CppOnlyBlocks cpp_only;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view row = text.substr(start, end - start);
    ++line;
    start = end + 1;
    const std::string_view directive = trimmed(row);
    if (cpp_only.drops(directive) || directive == "#pragma once") continue;
    if (directive.starts_with("#include")) {
      const std::size_t open = row.find('"'), close = row.rfind('"');
      if (open == std::string_view::npos || close <= open)
        throw ShaderError(fmt::format("{}:{}: #include needs a quoted path", path, line));
      expandInto(row.substr(open + 1, close - open - 1), lookup, out, stack);
      continue;
    }
    if (directive.starts_with("#version"))
      throw ShaderError(fmt::format(
          "{}:{}: leave out #version; every stage is compiled as 450 core", path, line));
    out.text.append(row);
    out.text += '\n';
    out.lines.push_back({number, line});
  }
  if (cpp_only.open())
    throw ShaderError(fmt::format("{}: `#ifdef __cplusplus` without its #endif", path));
  stack.pop_back();
}

std::string stageName(GLenum type) {
  switch (type) {
    case GL_VERTEX_SHADER:
      return "vertex";
    case GL_FRAGMENT_SHADER:
      return "fragment";
    case GL_GEOMETRY_SHADER:
      return "geometry";
    case GL_COMPUTE_SHADER:
      return "compute";
  }
  return "shader";
}

}  // namespace

ExpandedSource expandIncludes(std::string_view path, std::string_view defines,
                              const GlslLookup& lookup) {
  ExpandedSource out;
  out.text = "#version 450 core\n";
  out.lines.push_back({SourceLine::kDefinesFile, 0});
  out.text += defines;
  if (!defines.empty() && defines.back() != '\n') out.text += '\n';
  const auto define_lines = int(std::count(out.text.begin(), out.text.end(), '\n')) - 1;
  for (int line = 1; line <= define_lines; ++line)
    out.lines.push_back({SourceLine::kDefinesFile, line});
  std::vector<std::string> stack;
  expandInto(path, lookup, out, stack);
  return out;
}

std::string translateInfoLog(std::string_view log, const ExpandedSource& source) {
  // Mesa: "0:12(3): error"; NVIDIA: "0(12) : error". The leading number is the source string,
  // always 0 here (one string per stage).
  static const std::regex location(R"((^|\n)\d+(?::(\d+)\(\d+\)|\((\d+)\)))");
  std::string out;
  std::string text(log);
  std::size_t copied = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), location);
       it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    const std::size_t line = std::stoul(m[2].matched ? m[2].str() : m[3].str());
    out.append(text, copied, std::size_t(m.position(0)) - copied);
    out += m[1].str();
    if (line == 0 || line > source.lines.size()) {
      out += fmt::format("?:{}", line);
    } else {
      const SourceLine origin = source.lines[line - 1];
      if (origin.file == SourceLine::kDefinesFile)
        out += fmt::format("defines:{}", origin.line);
      else
        out += fmt::format("{}:{}", source.files[std::size_t(origin.file)], origin.line);
    }
    copied = std::size_t(m.position(0) + m.length(0));
  }
  out.append(text, copied);
  while (!out.empty() && (out.back() == '\n' || out.back() == '\0')) out.pop_back();
  return out;
}

Program buildProgram(std::initializer_list<ShaderStage> stages, std::string_view defines,
                     const GlslLookup& lookup) {
  std::string label;  // the stages' files, which name the program in errors
  for (const ShaderStage& stage : stages) label += (label.empty() ? "" : ", ") + stage.path;
  Program program(glCreateProgram(), label);
  std::vector<GLuint> shaders;
  auto cleanup = [&] {
    for (GLuint s : shaders) glDeleteShader(s);
  };
  for (const ShaderStage& stage : stages) {
    const ExpandedSource source = expandIncludes(stage.path, defines, lookup);
    const GLuint shader = glCreateShader(stage.type);
    shaders.push_back(shader);
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (glFaultInjected(GlFault::kShaderCompile)) {
      cleanup();
      throw ShaderError(
          fmt::format("{} shader {} does not compile:\n{}: error: injected by "
                      "GIB_GL_FAULT=shader-compile",
                      stageName(stage.type), stage.path, stage.path));
    }
    if (!ok) {
      GLint length = 0;
      glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
      std::string log(std::size_t(std::max(length, 1)), '\0');
      glGetShaderInfoLog(shader, length, nullptr, log.data());
      cleanup();
      throw ShaderError(fmt::format("{} shader {} does not compile:\n{}", stageName(stage.type),
                                    stage.path, translateInfoLog(log, source)));
    }
    glAttachShader(program.id(), shader);
  }
  glLinkProgram(program.id());
  cleanup();
  GLint ok = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program.id(), length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    throw ShaderError(fmt::format("program ({}) does not link:\n{}", label, log));
  }
  return program;
}

Program buildLayeredProgram(const LayeredStages& stages, std::string_view defines,
                            bool geometry_only, InstanceTarget target) {
  const bool layer = target == InstanceTarget::kLayer;
  const std::array<const char*, 2> candidates = {
      "GL_ARB_shader_viewport_layer_array",
      layer ? "GL_AMD_vertex_shader_layer" : "GL_AMD_vertex_shader_viewport_index"};
  std::string extension;
  if (!geometry_only)
    for (const char* name : candidates)
      if (extension.empty() && hasExtension(name)) extension = name;
  if (extension.empty())
    return buildProgram({{GL_VERTEX_SHADER, stages.vertex},
                         {GL_GEOMETRY_SHADER, stages.geometry},
                         {GL_FRAGMENT_SHADER, stages.fragment}},
                        defines);
  return buildProgram({{GL_VERTEX_SHADER, stages.vertex}, {GL_FRAGMENT_SHADER, stages.fragment}},
                      fmt::format("#extension {} : require\n#define {}_FROM_VERTEX_SHADER 1\n",
                                  extension, layer ? "LAYER" : "VIEWPORT") +
                          std::string(defines));
}

}  // namespace gib::rt::gl
