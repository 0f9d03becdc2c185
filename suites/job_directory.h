// The files a run's jobs write, named in this one place (the run's own files, run-state.json and
// results.json, are suites/run_directory.h's):
//
//   DIR/jobs/<slug>/               one directory per job
//     image.exr, image.png         the job's render: a technique's frame, or a reference job's
//                                  independent render at its last checkpoint; a technique's
//                                  auxiliary images beside them (realtime/technique_output.h)
//     timings.json                 a technique job's per-pass timings, with every frame's samples
//     reference.png                the reference of the job's class, for looking at
//     difference.png, flip.png     the render's error maps against it
//     disagreement.png             the pixels whose primary hit the G-buffer and the reference's
//                                  camera rays disagree on
//     thumbnail.png                the picture at thumbnail width, when it is wider
//     viewer.js                    the report viewer's linear data of the render and its FLIP map
//     result.json                  the job's result, written last: its presence means done
//     failed.json                  or why the job failed
//   DIR/references/<key>.exr       a full-precision copy of each reference the run measured
//                                  against, so that the run directory stands alone
//   DIR/viewer/<key>.js            the viewer's data of each reference (mean, standard error)
//
// The results record these paths relative to DIR (results::JobOutputs), so their consumers (the
// report, `gibench merge`) find the files without this header.
#pragma once

#include <filesystem>
#include <string>

namespace gib::suites {

struct JobDirectory {
  // The directory of the job with this slug in the run directory `run_dir`.
  JobDirectory(const std::filesystem::path& run_dir, const std::string& slug);

  std::filesystem::path run_dir;
  std::filesystem::path dir;
  std::filesystem::path image_exr;
  std::filesystem::path timings_json;
  std::filesystem::path reference_png;
  std::filesystem::path difference_png;
  std::filesystem::path flip_png;
  std::filesystem::path disagreement_png;
  std::filesystem::path thumbnail_png;
  std::filesystem::path viewer_data;
  std::filesystem::path result_json;
  std::filesystem::path failed_json;

  // The run's files that every job measured against the reference of store key `key` shares.
  std::filesystem::path referenceCopy(const std::string& key) const;
  std::filesystem::path referenceViewerData(const std::string& key) const;

  // `path`, a file of the run, as the results record it: relative to the run directory, with '/'
  // separators.
  std::string relative(const std::filesystem::path& path) const;
};

}  // namespace gib::suites
