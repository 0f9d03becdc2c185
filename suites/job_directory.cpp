#include "suites/job_directory.h"

namespace gib::suites {

namespace fs = std::filesystem;

JobDirectory::JobDirectory(const fs::path& run, const std::string& slug)
    : run_dir(run),
      dir(run / "jobs" / slug),
      image_exr(dir / "image.exr"),
      timings_json(dir / "timings.json"),
      reference_png(dir / "reference.png"),
      difference_png(dir / "difference.png"),
      flip_png(dir / "flip.png"),
      disagreement_png(dir / "disagreement.png"),
      thumbnail_png(dir / "thumbnail.png"),
      viewer_data(dir / "viewer.js"),
      result_json(dir / "result.json"),
      failed_json(dir / "failed.json") {}

fs::path JobDirectory::referenceCopy(const std::string& key) const {
  return run_dir / "references" / (key + ".exr");
}

fs::path JobDirectory::referenceViewerData(const std::string& key) const {
  return run_dir / "viewer" / (key + ".js");
}

std::string JobDirectory::relative(const fs::path& path) const {
  return path.lexically_relative(run_dir).generic_string();
}

}  // namespace gib::suites
