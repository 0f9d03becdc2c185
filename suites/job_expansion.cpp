#include "suites/job_expansion.h"

#include "common/content_hash.h"

#include <fmt/format.h>

#include <cctype>
#include <set>

namespace gib::suites {

namespace {

constexpr std::size_t kMaxSlugLength = 120;

// Letters, digits, '.', '_' and '-' stay; a vector's commas and anything else become '_'.
std::string slugPart(std::string_view text) {
  std::string part(text);
  for (char& c : part)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
  return part;
}

std::string shortHash(std::string_view text) {
  ContentHasher hasher;
  hasher.addString(text);
  return hasher.hexDigest().substr(0, 8);
}

struct Dimension {
  const Sweep* sweep;
  bool scene;  // a scene_set key
};

}  // namespace

std::vector<std::string> assignmentStrings(const Assignments& assignments) {
  std::vector<std::string> strings;
  for (const auto& [key, value] : assignments) strings.push_back(key + "=" + value);
  return strings;
}

std::vector<Job> expandSuite(const Suite& suite) {
  std::vector<Job> jobs;
  std::set<std::string> slugs;
  for (const Case& c : suite.cases) {
    std::vector<Dimension> dimensions;
    for (const Sweep& sweep : c.scene_parameters) dimensions.push_back({&sweep, true});
    for (const Sweep& sweep : c.technique_parameters) dimensions.push_back({&sweep, false});

    // An odometer over the sweeps, the last dimension turning fastest.
    std::vector<std::size_t> index(dimensions.size(), 0);
    for (bool more = true; more;) {
      Job job;
      job.suite = suite.name;
      job.case_name = c.name;
      job.scene = c.scene;
      job.technique = c.technique;
      job.settings = c.settings;

      std::string id_suffix;
      std::string slug = slugPart(c.name);
      for (std::size_t d = 0; d < dimensions.size(); ++d) {
        const Sweep& sweep = *dimensions[d].sweep;
        const std::string& value = sweep.values[index[d]];
        (dimensions[d].scene ? job.scene_parameters : job.technique_parameters)
            .emplace_back(sweep.key, value);
        if (!sweep.swept) continue;
        const std::string key = dimensions[d].scene ? "scene." + sweep.key : sweep.key;
        id_suffix += fmt::format("{}{}={}", id_suffix.empty() ? "" : ",", key, value);
        slug += fmt::format("__{}-{}", slugPart(key), slugPart(value));
      }
      job.id = id_suffix.empty() ? c.name : c.name + "/" + id_suffix;
      const bool hashed = slug.size() > kMaxSlugLength || slugs.count(slug) > 0;
      if (slug.size() > kMaxSlugLength) slug.resize(kMaxSlugLength - 9);
      if (hashed) {
        slug += '-';
        slug += shortHash(job.id);
      }
      slugs.insert(slug);
      job.slug = std::move(slug);
      jobs.push_back(std::move(job));

      more = false;
      for (std::size_t d = dimensions.size(); d-- > 0;) {
        if (++index[d] < dimensions[d].sweep->values.size()) {
          more = true;
          break;
        }
        index[d] = 0;
      }
    }
  }
  return jobs;
}

}  // namespace gib::suites
