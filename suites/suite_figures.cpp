#include "suites/suite_figures.h"

#include "common/join.h"
#include "realtime/technique.h"
#include "suites/suite_annotations.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <string_view>
#include <utility>

namespace gib::suites {

namespace {

// A figure wider than this is not a figure of a document; the bound catches a typo (columns =
// 300) before it lays out a page of empty cells.
constexpr long long kMaxColumns = 64;
constexpr long long kMaxRow = 1000;
// Job ids listed in the fix of an unknown job; a nightly suite has dozens.
constexpr std::size_t kListedJobs = 12;

constexpr std::string_view kAuxiliaryPrefix = "aux:";
constexpr const char* kImageChoices =
    "image, reference, difference, flip or aux:<name> (an auxiliary image of the technique, e.g. "
    "aux:atlas)";

// The name becomes a file name (report/figure-<name>.html, figures/<name>.png).
bool isSlug(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
  });
}

std::string jobChoices(const std::vector<Job>& jobs) {
  std::vector<std::string> ids;
  for (std::size_t i = 0; i < jobs.size() && i < kListedJobs; ++i) ids.push_back(jobs[i].id);
  std::string listed = joinNames(ids, ", ");
  if (jobs.size() > kListedJobs)
    listed += fmt::format(" and {} more (`gibench run --list`)", jobs.size() - kListedJobs);
  return listed;
}

bool validImage(std::string_view image) {
  if (image.starts_with(kAuxiliaryPrefix)) return image.size() > kAuxiliaryPrefix.size();
  return image == "image" || image == "reference" || image == "difference" || image == "flip";
}

// A panel as read, before it has a cell: which of row and column the file gave.
struct PanelEntry {
  results::FigureSpec::Panel panel;
  const toml::table* table = nullptr;
  const toml::node* row = nullptr;
  const toml::node* column = nullptr;
};

class FigureReader {
 public:
  FigureReader(const TomlErrorReporter& errors, const std::vector<Job>& jobs)
      : errors_(errors), jobs_(jobs) {}

  results::FigureSpec read(const toml::table& table, std::size_t index) {
    const std::vector<std::string> keys = {"name", "title", "caption", "columns", "panel"};
    const TomlTableReader first(errors_, table, "figure",
                                fmt::format("[[figure]] entry {}", index + 1), keys);
    const toml::node& name = first.require("name", "\"fig6\"");
    figure_ = {};
    figure_.name = first.string(name, "name");
    if (!isSlug(figure_.name))
      errors_.fail(name,
                   fmt::format("figure name '{}' has characters other than letters, digits, '-' "
                               "and '_'",
                               figure_.name),
                   "choose a name that can be a file name, e.g. \"fig6\"");
    for (const Job& job : jobs_)
      if (job.slug == "figure-" + figure_.name)
        errors_.fail(name,
                     fmt::format("figure '{}' would have the page of job '{}' "
                                 "(report/figure-{}.html)",
                                 figure_.name, job.id, figure_.name),
                     "give the figure another name");
    // Messages from here on name the figure.
    const TomlTableReader t(errors_, table, "figure", fmt::format("[[figure]] '{}'", figure_.name),
                            keys);
    figure_.title = t.string(t.require("title", "\"Fig. 6: the radiosity map\""), "title");
    if (const toml::node* n = t.find("caption")) figure_.caption = t.string(*n, "caption");

    std::vector<PanelEntry> entries;
    const std::vector<const toml::table*> panels = tomlTableArray(t, "panel");
    if (panels.empty())
      errors_.fail(table, fmt::format("figure '{}' has no panels", figure_.name),
                   "add [[figure.panel]] tables with job and image after the [[figure]]");
    for (std::size_t i = 0; i < panels.size(); ++i) entries.push_back(readPanel(*panels[i], i));

    figure_.columns = int(entries.size());
    if (const toml::node* n = t.find("columns"))
      figure_.columns = int(t.integer(*n, "columns", 1, kMaxColumns, "3"));
    place(entries);
    for (PanelEntry& entry : entries) figure_.panels.push_back(std::move(entry.panel));
    return figure_;
  }

 private:
  std::string panelName(std::size_t index) const {
    return fmt::format("figure '{}' panel {}", figure_.name, index + 1);
  }

  // An auxiliary image is declared by the job's technique (TechniqueInfo::auxiliary_images), so a
  // typo fails here rather than leaving an empty panel when the report is written.
  void checkAuxiliaryDeclared(const toml::node& node, const std::string& panel, const Job& job,
                              const std::string& image) const {
    if (job.technique == kReferenceTechnique)
      errors_.fail(node,
                   fmt::format("{}: job '{}' is a reference job, which has no auxiliary images",
                               panel, job.id),
                   "choose image, or a job of a real-time technique");
    const rt::TechniqueInfo& info = rt::findTechnique(job.technique);
    if (rt::findDeclaredOutput(info.auxiliary_images, image)) return;
    errors_.fail(
        node,
        fmt::format("{}: technique '{}' declares no auxiliary image '{}'", panel, job.technique,
                    image),
        info.auxiliary_images.empty()
            ? std::string("it writes none; choose image, reference or difference")
            : fmt::format("choose one of {} (`gibench list techniques`)",
                          joinNames(info.auxiliary_images, ", ",
                                    [](const rt::DeclaredOutput& o) { return "aux:" + o.name; })));
  }

  PanelEntry readPanel(const toml::table& table, std::size_t index) {
    const std::string name = panelName(index);
    const TomlTableReader t(
        errors_, table, "figure.panel",
        fmt::format("[[figure.panel]] {} of figure '{}'", index + 1, figure_.name),
        {"job", "image", "caption", "row", "column", "metric"});
    PanelEntry entry;
    entry.table = &table;
    results::FigureSpec::Panel& panel = entry.panel;

    const toml::node& job_node = t.require("job", "\"cornell-direct/shadow=pcf\"");
    panel.job = t.string(job_node, "job");
    const auto job =
        std::find_if(jobs_.begin(), jobs_.end(), [&](const Job& j) { return j.id == panel.job; });
    if (job == jobs_.end())
      errors_.fail(job_node,
                   fmt::format("{}: job '{}' is not a job of this suite", name, panel.job),
                   fmt::format("use one of its job ids: {}", jobChoices(jobs_)));

    const toml::node& image_node = t.require("image", "\"image\"");
    panel.image = t.string(image_node, "image");
    if (!validImage(panel.image))
      errors_.fail(image_node,
                   fmt::format("{}: image '{}' is not a picture of a job", name, panel.image),
                   fmt::format("choose {}", kImageChoices));
    if (panel.image.starts_with(kAuxiliaryPrefix))
      checkAuxiliaryDeclared(image_node, name, *job, panel.image.substr(kAuxiliaryPrefix.size()));
    const std::vector<std::string>& metrics = job->settings.metrics;
    if (panel.image == "flip" && std::find(metrics.begin(), metrics.end(), "flip") == metrics.end())
      errors_.fail(
          image_node,
          fmt::format("{}: job '{}' does not measure flip, so it has no FLIP map", name, panel.job),
          "add \"flip\" to the case's metrics, or choose image, reference or difference");

    if (const toml::node* n = t.find("caption")) panel.caption = t.string(*n, "caption");
    if ((entry.row = t.find("row"))) panel.row = int(t.integer(*entry.row, "row", 1, kMaxRow, "1"));
    if ((entry.column = t.find("column")))
      panel.column = int(t.integer(*entry.column, "column", 1, kMaxColumns, "1"));
    if (const toml::node* n = t.find("metric")) {
      panel.metric = t.string(*n, "metric");
      if (panel.metric != "none")
        checkQuantity(errors_, *n, name + "'s metric", panel.metric, *job);
    }
    return entry;
  }

  // Gives every panel its cell (the order is in suite_figures.h).
  void place(std::vector<PanelEntry>& entries) {
    std::map<std::pair<int, int>, std::size_t> taken;  // (row, column) -> panel index
    const int columns = figure_.columns;
    auto take = [&](std::size_t i, const toml::node& at) {
      results::FigureSpec::Panel& panel = entries[i].panel;
      const auto [it, inserted] = taken.emplace(std::pair(panel.row, panel.column), i);
      if (!inserted)
        errors_.fail(at,
                     fmt::format("figure '{}': panels {} and {} are both at row {}, column {}",
                                 figure_.name, it->second + 1, i + 1, panel.row, panel.column),
                     "give each panel a cell of its own, or leave out row and column to fill "
                     "the next free cell");
    };
    auto free = [&](int row, int column) { return !taken.contains({row, column}); };

    for (std::size_t i = 0; i < entries.size(); ++i) {
      PanelEntry& entry = entries[i];
      if (entry.column && entry.panel.column > columns)
        errors_.fail(
            *entry.column,
            fmt::format("{}: column {} is beyond the figure's {} column{}", panelName(i),
                        entry.panel.column, columns, columns == 1 ? "" : "s"),
            fmt::format("choose a column from 1 to {}, or raise the figure's columns", columns));
      if (entry.row && entry.column) take(i, *entry.column);
    }
    for (std::size_t i = 0; i < entries.size(); ++i) {
      PanelEntry& entry = entries[i];
      if (entry.row && !entry.column) {
        int column = 1;
        while (column <= columns && !free(entry.panel.row, column)) ++column;
        if (column > columns)
          errors_.fail(*entry.row,
                       fmt::format("{}: row {} has no free cell (all {} columns are taken)",
                                   panelName(i), entry.panel.row, columns),
                       "choose another row, give the panel a column, or raise the figure's "
                       "columns");
        entry.panel.column = column;
        take(i, *entry.row);
      } else if (entry.column && !entry.row) {
        int row = 1;
        while (!free(row, entry.panel.column)) ++row;
        entry.panel.row = row;
        take(i, *entry.column);
      }
    }
    for (std::size_t i = 0; i < entries.size(); ++i) {
      PanelEntry& entry = entries[i];
      if (entry.row || entry.column) continue;
      int cell = 0;
      while (!free(cell / columns + 1, cell % columns + 1)) ++cell;
      entry.panel.row = cell / columns + 1;
      entry.panel.column = cell % columns + 1;
      take(i, *entry.table);
    }
  }

  const TomlErrorReporter& errors_;
  const std::vector<Job>& jobs_;
  results::FigureSpec figure_;
};

}  // namespace

std::vector<results::FigureSpec> readFigures(const TomlTableReader& root,
                                             const std::vector<Job>& jobs) {
  std::vector<results::FigureSpec> figures;
  std::map<std::string, int> lines;  // figure name -> line of its [[figure]]
  FigureReader reader(root.errors(), jobs);
  const std::vector<const toml::table*> entries = tomlTableArray(root, "figure");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    results::FigureSpec figure = reader.read(*entries[i], i);
    const int line = int(std::max<toml::source_index>(entries[i]->source().begin.line, 1));
    if (const auto [it, inserted] = lines.emplace(figure.name, line); !inserted)
      root.errors().fail(*entries[i]->get("name"),
                         fmt::format("figure name '{}' is also the name of the figure at line {}",
                                     figure.name, it->second),
                         "give each figure its own name");
    figures.push_back(std::move(figure));
  }
  return figures;
}

}  // namespace gib::suites
