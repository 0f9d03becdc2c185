// The `--set` and `--scene-set` values (common/parameters.h): the input's first byte picks a
// parameter table (every built-in scene's and every technique's, as `gibench render`, `run` and
// `export-blender` parse them), the rest is the command line's assignments, one per line.
#include "common/parameters.h"
#include "fuzz/fuzz_support.h"
#include "realtime/technique.h"
#include "scene/builtin_scenes.h"

#include <string>
#include <vector>

namespace {

struct Table {
  std::string owner;
  const gib::ParameterTable* table;
};

std::vector<Table> allTables() {
  std::vector<Table> tables;
  for (const auto& scene : gib::scene::builtinScenes())
    tables.push_back({"scene '" + scene.name + "'", &scene.parameters});
  for (const auto& technique : gib::rt::techniqueCatalogue())
    tables.push_back({"technique '" + technique.name + "'", &technique.parameters});
  return tables;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t begin = 0;
  for (std::size_t end; (end = text.find('\n', begin)) != std::string::npos; begin = end + 1)
    out.push_back(text.substr(begin, end - begin));
  if (begin < text.size()) out.push_back(text.substr(begin));
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gib;
  static const std::vector<Table> tables = allTables();
  if (size == 0) return 0;
  const Table& table = tables[data[0] % tables.size()];
  const std::vector<std::string> assignments = lines(fuzz::inputText(data + 1, size - 1));
  fuzz::refusedOnlyAsInputError([&] {
    const ParameterValues values = parseParameters(*table.table, assignments, table.owner);
    // What every consumer does next: read each value back in its type, and the canonical text.
    for (const ParameterSpec& spec : *table.table) {
      switch (spec.type) {
        case ParameterType::kInteger:
          values.integer(spec.name);
          break;
        case ParameterType::kNumber:
          values.number(spec.name);
          break;
        case ParameterType::kVector3:
          values.vector3(spec.name);
          break;
        case ParameterType::kChoice:
          values.text(spec.name);
          break;
      }
    }
    values.canonical();
  });
  return 0;
}
