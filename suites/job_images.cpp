#include "suites/job_images.h"

#include "image/display.h"
#include "image/output_files.h"
#include "image/viewer_data.h"
#include "metrics/error_map_display.h"

#include <algorithm>
#include <cmath>
#include <system_error>

namespace gib::suites {

namespace {

namespace fs = std::filesystem;

// Thumbnails are at most this wide: a 100-job index stays light however large the images are.
constexpr int kThumbnailWidth = 128;

// The report viewer's linear data of the reference (mean and standard error of the mean), once
// per reference and run: every job measured against it shares the file.
std::string writeReferenceViewerData(const JobDirectory& files,
                                     const ref::StoredReference& reference) {
  const fs::path path = files.referenceViewerData(reference.entry.key);
  const std::string relative = files.relative(path);
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) return relative;  // written by another job of the run
  fs::create_directories(path.parent_path(), ec);
  image::Image standard_error;
  if (reference.variance.pixelCount() > 0) {
    standard_error = reference.variance;
    for (float& value : standard_error.data()) value = std::sqrt(std::max(value, 0.0f));
  }
  image::writeViewerData(path, relative,
                         {{"reference", &reference.mean}, {"stderr", &standard_error}});
  return relative;
}

}  // namespace

std::string copyReferenceExr(const JobDirectory& files, const ref::StoredReference& reference) {
  const fs::path path = files.referenceCopy(reference.entry.key);
  const std::string relative = files.relative(path);
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) return relative;  // copied by another job of the run
  fs::create_directories(path.parent_path(), ec);
  image::copyFileAtomically(reference.entry.dir / "reference.exr", path);
  return relative;
}

void writeComparisonImages(const JobDirectory& files, const ref::StoredReference& reference,
                           const image::Image& test, const metrics::MetricReport& report,
                           results::JobOutputs& outputs) {
  image::writePng(files.reference_png, reference.mean);
  outputs.reference_png = files.relative(files.reference_png);
  outputs.reference_exr = copyReferenceExr(files, reference);
  // A picture that is small enough already is its own thumbnail: no second copy of it.
  const image::Image& pictured = test.width() > 0 ? test : reference.mean;
  const std::string& small_enough = test.width() > 0 ? outputs.image_png : outputs.reference_png;
  if (pictured.width() <= kThumbnailWidth && !small_enough.empty()) {
    outputs.thumbnail_png = small_enough;
  } else {
    image::writePng(files.thumbnail_png, image::downsampleToWidth(pictured, kThumbnailWidth));
    outputs.thumbnail_png = files.relative(files.thumbnail_png);
  }
  outputs.reference_viewer_data = writeReferenceViewerData(files, reference);
  const image::Image* flip = nullptr;
  for (const auto& [name, map] : report.maps)
    if (name == "flip") flip = &map;
  outputs.viewer_data = files.relative(files.viewer_data);
  image::writeViewerData(files.viewer_data, outputs.viewer_data,
                         {{"image", &test}, {"flip", flip}});
  if (test.width() == 0) return;
  image::writePng(files.difference_png,
                  metrics::errorMapForDisplay(
                      "difference", metrics::absoluteLuminanceDifference(reference.mean, test)));
  outputs.difference_png = files.relative(files.difference_png);
  if (flip) {
    image::writePng(files.flip_png, metrics::errorMapForDisplay("flip", *flip));
    outputs.flip_png = files.relative(files.flip_png);
  }
}

}  // namespace gib::suites
